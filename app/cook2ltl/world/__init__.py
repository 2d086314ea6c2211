"""The world model: each primitive set's kinds, preconditions, effects and processes, as PDDL.

Read once with unified-planning (`pddl`), evaluated fast by our own interpreter of the parsed domain
(`logic`, held against unified-planning's simulator by the tests), planned with Fast Downward (`planner`).
Decoding, checking, completion and whole-recipe rollouts share it.
"""
