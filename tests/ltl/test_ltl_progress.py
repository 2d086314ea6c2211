"""Progression, verdicts, the monitor and the simplifier."""

from itertools import product

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cook2ltl.ltl.ast import FALSE, TRUE, Atom, holds_at_end
from cook2ltl.ltl.automaton import powerset_alphabet
from cook2ltl.ltl.parser import parse
from cook2ltl.ltl.progress import Verdict, holds, monitor, progress, progress_trace, verdict
from cook2ltl.ltl.simplify import EMPTY, NONEMPTY, simplify
from tests.ltl.ltl_testkit import formulas_strategy, sat, small_atoms, traces_strategy

ATOMS = small_atoms(3)
p0, p1, p2 = ATOMS
formulas = formulas_strategy(atoms=st.sampled_from(ATOMS), max_leaves=10)
traces = traces_strategy(ATOMS, max_len=6)
ALL_STEPS = powerset_alphabet(ATOMS)


def steps(*names):
    """steps("a", "", "b c") -> [{a}, {}, {b, c}]"""
    return [frozenset(Atom(n) for n in s.split()) for s in names]


def test_sequence_leaves_the_rest_readable():
    f = parse("F(a & F(b & F c))")
    assert progress(f, {Atom("a")}) is parse("F(b & F c)")
    assert progress_trace(f, steps("a", "b")) is parse("F c")
    psi = parse("F(stir U thickened)")
    assert progress(parse("F(a & F(stir U thickened))"), {Atom("a")}) is psi


def test_monitor_reports_every_step():
    results = list(monitor(parse("F(a & F b) & G !burnt"), steps("a", "", "b", "burnt")))
    assert [r.index for r in results] == [1, 2, 3, 4]
    assert [str(r.remaining) for r in results] == ["◇b ∧ □¬burnt", "◇b ∧ □¬burnt", "□¬burnt", "⊥"]
    assert [r.verdict for r in results] == [
        Verdict.PRESUMABLY_FALSE,
        Verdict.PRESUMABLY_FALSE,
        Verdict.PRESUMABLY_TRUE,
        Verdict.VIOLATED,
    ]


def test_verdicts():
    assert verdict(TRUE) is Verdict.SATISFIED and verdict(FALSE) is Verdict.VIOLATED
    assert verdict(parse("G a")) is Verdict.PRESUMABLY_TRUE
    assert verdict(parse("F a")) is Verdict.PRESUMABLY_FALSE
    assert list(monitor(parse("F a"), steps("a")))[0].verdict is Verdict.SATISFIED
    assert Verdict.PRESUMABLY_TRUE.holds and not Verdict.PRESUMABLY_FALSE.holds


def test_weak_and_strong_next_at_the_end_of_a_recipe():
    # Spot's LTLf reading: X is weak, X[!] strong.
    assert holds(parse("X a"), steps("b"))
    assert not holds(parse("X[!] a"), steps("b"))
    assert not holds(parse("X[!] true"), steps(""))
    assert holds(parse("X[!] true"), steps("", ""))
    assert holds(parse("X false"), steps(""))
    # X[!] of something true on an empty rest still needs the step to exist.
    assert progress(parse("X[!] G a"), steps("")[0]) is parse("G a & F true")
    assert progress(parse("X F a"), steps("")[0]) is parse("F a | G false")


def test_end_of_trace_reading():
    for text in ["G a", "a R b", "a W b", "X a", "!F a", "true", "!a", "a -> b", "F a <-> b"]:
        assert holds_at_end(parse(text)), text
    for text in ["F a", "a U b", "a M b", "X[!] a", "a", "!G a", "false", "!a -> b"]:
        assert not holds_at_end(parse(text)), text


@settings(max_examples=400, deadline=None)
@given(formulas, traces)
def test_monitor_agrees_with_textbook_semantics(f, trace):
    """After every step: verdict.holds == the trace so far satisfies f."""
    for k, result in enumerate(monitor(f, trace), start=1):
        assert result.verdict.holds == sat(f, trace[:k]), (f, trace[:k], result)


@settings(max_examples=200, deadline=None)
@given(formulas, traces)
def test_satisfied_and_violated_are_final(f, trace):
    """SATISFIED (VIOLATED) means every extension by up to two steps does (not) satisfy."""
    extensions = [[]] + [[s] for s in ALL_STEPS] + [list(p) for p in product(ALL_STEPS, repeat=2)]
    for k, result in enumerate(monitor(f, trace), start=1):
        if result.verdict in (Verdict.SATISFIED, Verdict.VIOLATED):
            want = result.verdict is Verdict.SATISFIED
            assert all(sat(f, trace[:k] + ext) == want for ext in extensions), (f, trace[:k])


@settings(max_examples=400, deadline=None)
@given(formulas, traces)
def test_simplify_keeps_the_meaning(f, trace):
    g = simplify(f)
    assert holds_at_end(g) == holds_at_end(f)
    for k in range(1, len(trace) + 1):
        assert sat(g, trace[:k]) == sat(f, trace[:k]), (f, g, trace[:k])


@settings(max_examples=200, deadline=None)
@given(formulas)
def test_simplify_is_idempotent_and_never_grows(f):
    g = simplify(f)
    assert simplify(g) is g
    assert g.size <= f.size + 2  # a constant operand may become "◇⊤ ∧ …" at most


@pytest.mark.parametrize(
    "text, simpler",
    [
        ("F F a", "F a"),
        ("G G a", "G a"),
        ("true U a", "F a"),
        ("false R a", "G a"),
        ("a U false", "false"),
        ("a W false", "G a"),
        ("a M true", "F a"),
        ("a & !a", "false"),
        ("F a | F(b & F a)", "F a"),
        ("G a & (G a | b)", "G a"),
        ("true -> a", "a"),
        ("a -> false", "!a"),
        ("false <-> a", "!a"),
        ("X true", "true"),
        ("X[!] false", "false"),
    ],
)
def test_simplifier_rules(text, simpler):
    assert simplify(parse(text)) is parse(simpler)


def test_simplifier_keeps_what_only_holds_on_nonempty_traces():
    # On the empty rest of a trace ◇⊤ is false and □⊥ true: not rewritten to ⊤, ⊥.
    assert simplify(parse("a | !a")) is parse("true")
    assert simplify(parse("F true")) is NONEMPTY
    assert simplify(parse("G false")) is EMPTY
    assert simplify(parse("a U true")) is NONEMPTY
