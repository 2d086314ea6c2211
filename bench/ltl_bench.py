"""Benchmark of the LTL engine (a script, not a test).

    python bench/ltl_bench.py

Targets from issue 3: progression ≤ 0.2 ms per step on a 30-action recipe
formula; the DFA of a 30-action sequence built in ≤ 100 ms. "Cold" runs
start with empty memo tables, "warm" ones replay the same trace.
"""

from __future__ import annotations

import statistics
import time
from functools import partial

from cook2ltl.ltl import Atom, clear_caches, monitor
from cook2ltl.ltl.automaton import build_dfa, minimise
from cook2ltl.ltl.patterns import all_of, avoid, hold_until, sequenced_visit

RUNS = 20


def recipe_actions() -> list[Atom]:
    """30 primitive actions of a made-up pasta bake, with arguments."""
    verbs = ["pick_up", "put", "slice", "pour", "stir", "open", "close", "turn_on", "turn_off", "wait"]
    objects = ["knife", "tomato", "pot", "water", "pasta", "oven", "cheese", "dish", "sauce", "lid"]
    return [Atom(verbs[i % 10], (objects[(i * 3) % 10], f"step{i}")) for i in range(30)]


def recipe_formula(actions: list[Atom]):
    """A sequenced visit over the 30 actions with Until, all-of and avoid mixed in."""
    boiling, burnt = Atom("boiling", ("water",)), Atom("burnt", ("sauce",))
    elements = [
        *actions[:5],
        hold_until(actions[5], boiling),
        *actions[6:12],
        all_of(actions[12], actions[13]),
        avoid(burnt),
        *actions[14:25],
        all_of(actions[25], actions[26], actions[27]),
        *actions[28:],
    ]
    return sequenced_visit(*elements), boiling


def recipe_trace(actions: list[Atom], boiling: Atom) -> list[frozenset[Atom]]:
    """The recipe done in order, with idle steps in between and some repeats."""
    idle = frozenset({Atom("look_around")})
    trace = []
    for i, action in enumerate(actions):
        trace.append(frozenset({action} | ({boiling} if i == 6 else set())))
        if i % 4 == 0:
            trace += [idle, frozenset({action})]
    return trace


def time_ms(fn) -> float:
    start = time.perf_counter()
    fn()
    return (time.perf_counter() - start) * 1000


def main() -> None:
    actions = recipe_actions()
    sequence = sequenced_visit(*actions)
    # The very first build also pays Python's one-time costs (first calls, allocations).
    first_build = time_ms(lambda: build_dfa(sequence))
    formula, boiling = recipe_formula(actions)
    trace = recipe_trace(actions, boiling)
    results = list(monitor(formula, trace))
    assert results[-1].verdict.holds, "the benchmark trace should satisfy the recipe"

    def run_monitor():
        for _ in monitor(formula, trace):
            pass

    cold = []
    for _ in range(RUNS):
        clear_caches()
        cold.append(time_ms(run_monitor) / len(trace))
    warm = [time_ms(run_monitor) / len(trace) for _ in range(RUNS)]
    print(f"recipe formula: {len(actions)} actions, {formula.size} nodes; trace of {len(trace)} steps")
    print(f"progression, cold: {statistics.median(cold):.4f} ms/step median, {max(cold):.4f} max")
    print(f"progression, warm: {statistics.median(warm):.4f} ms/step median, {max(warm):.4f} max")

    builds, minimising, states = [], [], 0
    for _ in range(RUNS):
        clear_caches()
        start = time.perf_counter()
        dfa = build_dfa(sequence)
        builds.append((time.perf_counter() - start) * 1000)
        minimising.append(time_ms(partial(minimise, dfa)))
        states = len(dfa.states)
    print(
        f"DFA of a 30-action sequence ({states} states, {len(dfa.alphabet)} letters), cold: "
        f"{statistics.median(builds):.1f} ms median, {max(builds):.1f} max; "
        f"minimise {statistics.median(minimising):.1f} ms; first build in this process {first_build:.1f} ms"
    )
    clear_caches()
    start = time.perf_counter()
    recipe_dfa = build_dfa(formula)
    recipe_build = (time.perf_counter() - start) * 1000
    print(f"DFA of the recipe formula above ({len(recipe_dfa.states)} states), cold: {recipe_build:.1f} ms")


if __name__ == "__main__":
    main()
