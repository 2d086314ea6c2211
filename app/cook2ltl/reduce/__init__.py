"""Stage 3 of Algorithm 1: reduce a high-level action to admissible primitives with a constrained LLM.

primitives (the set 𝒜 as data) · action (frames as calls) · prompt · grammar · llm (backend, loaded
lazily) · reduction · body (plan lines, made parametric for the library).
"""
