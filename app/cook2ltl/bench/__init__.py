"""Benchmarks behind `cook2ltl bench`: the paper's Tables I and II, the span model against spaCy, micro timings.

Measurements, not tests: each module runs the real models and writes JSON and a markdown table under
`--out` (bench/results/ in a checkout). Heavy libraries are imported inside the functions that use them.
"""
