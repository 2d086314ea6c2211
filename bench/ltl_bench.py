"""Benchmark of the LTL engine (a script, not a test); `cook2ltl bench micro` includes it.

    python bench/ltl_bench.py

What it measures and the targets: cook2ltl.bench.ltl.
"""

from __future__ import annotations

from cook2ltl.bench.ltl import measure_ltl


def main() -> None:
    r = measure_ltl()
    cold, warm, dfa = r["progress_ms_per_step_cold"], r["progress_ms_per_step_warm"], r["dfa_sequence_ms"]
    print(f"recipe formula: 30 actions, {r['formula_nodes']} nodes; trace of {r['trace_steps']} steps")
    print(f"progression, cold: {cold['median']:.4f} ms/step median, {cold['max']:.4f} max")
    print(f"progression, warm: {warm['median']:.4f} ms/step median, {warm['max']:.4f} max")
    print(f"DFA of a 30-action sequence ({r['dfa_sequence_states']} states, {r['dfa_sequence_letters']} letters), "
          f"cold: {dfa['median']:.1f} ms median, {dfa['max']:.1f} max; minimise {r['minimise_ms']:.1f} ms; "
          f"first build in this process {dfa['first']:.1f} ms")
    print(f"DFA of the recipe formula above, cold: {r['dfa_recipe_ms']:.1f} ms")


if __name__ == "__main__":
    main()
