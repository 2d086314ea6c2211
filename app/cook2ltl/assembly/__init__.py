"""Everything built from settings: models (`manifest`, `provision`, `backends`), translators and the rule for
checking in the kitchen (`translators`), a task's plan (`planning`) and trial (`trial`), and `doctor`.

The command line, the app and the benchmarks ask this package for what they run, so each decision is made once.
"""
