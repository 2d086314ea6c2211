"""Speed of the LTL engine: progression per step and DFA construction on a 30-action recipe formula.

Targets from issue 3: progression ≤ 0.2 ms per step on a 30-action recipe formula; the DFA of a 30-action
sequence built in ≤ 100 ms. "Cold" runs start with empty memo tables, "warm" ones replay the same trace.
"""

from __future__ import annotations

import statistics
import time
from functools import partial

from cook2ltl.ltl import Atom, clear_caches, monitor
from cook2ltl.ltl.automaton import build_dfa, minimise
from cook2ltl.ltl.patterns import all_of, avoid, hold_until, sequenced_visit


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


def measure_ltl(runs: int = 20) -> dict:
    """Medians and maxima over `runs` of progression per step and of DFA construction."""
    actions = recipe_actions()
    sequence = sequenced_visit(*actions)
    first_build = time_ms(lambda: build_dfa(sequence))  # also pays Python's one-time costs
    formula, boiling = recipe_formula(actions)
    trace = recipe_trace(actions, boiling)
    if not list(monitor(formula, trace))[-1].verdict.holds:
        raise AssertionError("the benchmark trace should satisfy the recipe formula")

    def run_monitor():
        for _ in monitor(formula, trace):
            pass

    cold = []
    for _ in range(runs):
        clear_caches()
        cold.append(time_ms(run_monitor) / len(trace))
    warm = [time_ms(run_monitor) / len(trace) for _ in range(runs)]
    builds, minimising = [], []
    for _ in range(runs):
        clear_caches()
        start = time.perf_counter()
        dfa = build_dfa(sequence)
        builds.append((time.perf_counter() - start) * 1000)
        minimising.append(time_ms(partial(minimise, dfa)))
    clear_caches()
    recipe_build = time_ms(lambda: build_dfa(formula))
    return {
        "formula_nodes": formula.size, "trace_steps": len(trace), "runs": runs,
        "progress_ms_per_step_cold": {"median": statistics.median(cold), "max": max(cold)},
        "progress_ms_per_step_warm": {"median": statistics.median(warm), "max": max(warm)},
        "dfa_sequence_states": len(dfa.states), "dfa_sequence_letters": len(dfa.alphabet),
        "dfa_sequence_ms": {"median": statistics.median(builds), "max": max(builds), "first": first_build},
        "minimise_ms": statistics.median(minimising), "dfa_recipe_ms": recipe_build,
    }
