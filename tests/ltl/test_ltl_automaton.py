"""DFA by progression: language, minimisation, dead states, satisfiability."""

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cook2ltl.ltl.ast import Atom
from cook2ltl.ltl.automaton import (
    AutomatonTooLarge,
    action_alphabet,
    build_dfa,
    dead_states,
    is_satisfiable,
    minimise,
    powerset_alphabet,
)
from cook2ltl.ltl.parser import parse
from cook2ltl.ltl.patterns import sequenced_visit
from cook2ltl.ltl.progress import holds
from tests.ltl.ltl_testkit import formulas_strategy, sat, small_atoms, traces_strategy

ATOMS = small_atoms(3)
ALPHABET = powerset_alphabet(ATOMS)
formulas = formulas_strategy(atoms=st.sampled_from(ATOMS), max_leaves=8)
traces = traces_strategy(ATOMS, max_len=7)


@settings(max_examples=150, deadline=None)
@given(formulas, st.lists(traces, min_size=1, max_size=5))
def test_dfa_accepts_what_the_formula_holds_on(f, some_traces):
    dfa = build_dfa(f, ALPHABET)
    small = minimise(dfa)
    assert len(small.states) <= len(dfa.states)
    for trace in some_traces:
        assert dfa.accepts(trace) == holds(f, trace) == small.accepts(trace)
        if trace:
            assert dfa.accepts(trace) == sat(f, trace)


@settings(max_examples=100, deadline=None)
@given(formulas)
def test_minimise_is_minimal_and_stable(f):
    small = minimise(build_dfa(f, ALPHABET))
    assert len(minimise(small).states) == len(small.states)
    dead = dead_states(small)
    assert len(dead) <= 1  # a minimal DFA has at most one sink that never accepts


@settings(max_examples=100, deadline=None)
@given(formulas, traces)
def test_dead_states_can_never_accept(f, trace):
    dfa = build_dfa(f, ALPHABET)
    if dfa.run(trace) in dead_states(dfa):
        extensions = [[s] for s in ALPHABET] + [[s, t] for s in ALPHABET for t in ALPHABET]
        assert not any(sat(f, trace + ext) for ext in extensions)


def test_recipe_dfa_over_actions_and_predicates():
    f = parse("F(a & F(stir U thickened)) & G !burn")
    dfa = build_dfa(f, action_alphabet(f.atoms, predicates={"thickened"}))
    a, stir, thickened, burn = (Atom(n) for n in ("a", "stir", "thickened", "burn"))
    assert len(dfa.alphabet) == 8  # (no action, a, stir, burn) x (thickened or not)
    assert frozenset({a, thickened}) in dfa.alphabet
    assert frozenset({a, stir}) not in dfa.alphabet  # one action per step
    assert [str(s) for s in dfa.states] == [
        "◇(a ∧ ◇(stir 𝒰 thickened)) ∧ □¬burn",
        "◇(stir 𝒰 thickened) ∧ □¬burn",
        "□¬burn",
        "⊥",
    ]
    assert dfa.accepting == {2}
    assert dead_states(dfa) == {3}
    assert dfa.run([{burn}]) == 3


def test_satisfiability():
    assert is_satisfiable(parse("F(a & F b)"))
    assert not is_satisfiable(parse("F(a & b)"))  # two actions at once
    assert is_satisfiable(parse("F(a & b)"), powerset_alphabet(parse("a & b").atoms))
    assert not is_satisfiable(parse("G a & F !a"), powerset_alphabet([Atom("a")]))
    assert not is_satisfiable(parse("X[!] false"))
    assert is_satisfiable(parse("X false"))  # a one-step trace
    assert is_satisfiable(
        parse("F(cold(apple) & open(fridge))"),
        action_alphabet(parse("cold(apple) & open(fridge)").atoms, predicates={"cold"}),
    )


def test_thirty_action_sequence():
    actions = [Atom("do", (str(i),)) for i in range(30)]
    dfa = build_dfa(sequenced_visit(*actions))
    assert len(dfa.states) == 31 and len(minimise(dfa).states) == 31
    assert dfa.accepts([{a} for a in actions])
    assert not dfa.accepts([{a} for a in actions[:-1]])
    assert dead_states(dfa) == frozenset()


def test_state_budget_and_unknown_letters():
    with pytest.raises(AutomatonTooLarge):
        build_dfa(sequenced_visit(*small_atoms(5)), max_states=3)
    dfa = build_dfa(parse("F(a & F b)"))
    with pytest.raises(ValueError, match="not a letter"):
        dfa.run([{Atom("a"), Atom("b")}])
    assert dfa.accepts([{Atom("a"), Atom("other")}, {Atom("b")}])
