"""The sequenced-visit builder and the atom checks."""

from dataclasses import dataclass

import pytest

from cook2ltl.ltl.ast import Atom, postorder
from cook2ltl.ltl.atoms import AtomKind, atom_kind, check_against, check_atoms, split_atoms
from cook2ltl.ltl.parser import parse
from cook2ltl.ltl.patterns import (
    all_of,
    any_of,
    avoid,
    hold_until,
    sequenced_visit,
    then,
)
from cook2ltl.ltl.printer import to_spot, to_unicode
from cook2ltl.ltl.progress import Verdict, holds, monitor, progress_trace
from cook2ltl.ltl.simplify import simplify

a, b, c, d = (Atom(n) for n in "abcd")
stir, thickened = Atom("stir"), Atom("thickened")


def trace(*names):
    return [frozenset(Atom(n) for n in s.split()) for s in names]


def test_paper_pattern():
    assert sequenced_visit(a, b, c) is parse("F(a & F(b & F c))")
    assert sequenced_visit(a) is parse("F a")
    assert sequenced_visit() is parse("true")


def test_until_goes_inside_the_sequence():
    f = sequenced_visit(a, hold_until(stir, thickened))
    assert f is parse("F(a & F(stir U thickened))")
    recipe = trace("a", "stir", "stir", "stir thickened")
    assert holds(f, recipe)
    # Beside the action, the Until has to start at a's own step, where the
    # robot does a, not stir: that action violates it.
    beside = parse("F(a & (stir U thickened))")
    assert not holds(beside, recipe)
    assert list(monitor(parse("a & (stir U thickened)"), trace("a")))[0].verdict is Verdict.VIOLATED


def test_sequence_goes_on_once_the_goal_holds():
    f = sequenced_visit(a, hold_until(stir, thickened), b)
    assert f is parse("F(a & F(stir U (thickened & F b)))")
    assert holds(f, trace("a", "stir", "stir thickened", "b"))
    assert not holds(f, trace("a", "stir", "b", "stir thickened"))


def test_all_of_and_any_of():
    f = sequenced_visit(a, all_of(b, c), d)
    assert f is parse("F(a & F(b & F d) & F(c & F d))")
    assert holds(f, trace("a", "c", "b", "d"))
    assert not holds(f, trace("a", "c", "d", "b"))
    g = sequenced_visit(a, any_of(b, c), d)
    assert g is parse("F(a & (F(b & F d) | F(c & F d)))")
    assert holds(g, trace("a", "c", "d"))


def test_avoid_holds_until_the_next_element():
    f = sequenced_visit(a, avoid(c), b)
    assert f is parse("F(a & (!c U b))")
    assert holds(f, trace("c", "a", "b", "c"))
    assert not holds(f, trace("a", "c", "b"))
    assert sequenced_visit(a, avoid(c)) is parse("F(a & G !c)")


def test_sub_sequences_splice():
    plan = then(Atom("pick_up", ("knife",)), Atom("slice", ("tomato",)))
    assert sequenced_visit(a, plan, b) is sequenced_visit(a, *plan.parts, b)
    with pytest.raises(TypeError):
        sequenced_visit("a")


def test_long_recipes_nest_deeper_than_python_recursion_allows():
    actions = [Atom("do", (str(i),)) for i in range(600)]
    f = sequenced_visit(*actions[:300], avoid(Atom("burnt")), all_of(a, b), *actions[300:])
    assert parse(to_spot(f)) is f and parse(to_unicode(f)) is f
    assert simplify(f) is f
    steps = [{x} for x in actions[:300]] + [{b}, {a}] + [{x} for x in actions[300:]]
    assert list(monitor(f, steps))[-1].verdict is Verdict.SATISFIED


def test_all_of_in_a_row_shares_the_rest_of_the_sequence():
    # 40 pairs: the formula's text would repeat the rest 2^40 times, but the
    # hash-consed AST shares it, and monitoring works on the shared nodes.
    pairs = [(Atom("add", (f"x{i}",)), Atom("add", (f"y{i}",))) for i in range(40)]
    f = sequenced_visit(*(all_of(x, y) for x, y in pairs))
    assert f.size > 2**40
    assert sum(1 for _ in postorder(f)) < 400
    steps = [{step} for x, y in pairs for step in (y, x)]
    assert list(monitor(f, steps))[-1].verdict is Verdict.SATISFIED
    assert str(progress_trace(f, steps[:-2])) == "◇add(x39) ∧ ◇add(y39)"


PRIMITIVES = {"pick_up": 1, "slice": 2, "put": 2, "cold": 1}


def test_atom_checks():
    f = parse("F(pick_up(knife) & F slice(tomato) & F pikc_up(x)) & G !cold(apple, fridge)")
    problems = {p.atom.text: p.message for p in check_atoms(f, PRIMITIVES, {"cold"})}
    assert problems == {
        "cold(apple, fridge)": "predicate 'cold' takes 1 argument, got 2 in cold(apple, fridge)",
        "pikc_up(x)": "unknown action 'pikc_up'; did you mean 'pick_up'?",
        "slice(tomato)": "action 'slice' takes 2 arguments, got 1 in slice(tomato)",
    }
    assert check_atoms(parse("F put(knife, drawer)"), PRIMITIVES) == ()


def test_actions_and_state_predicates():
    f = parse("F(pick_up(apple) & F cold(apple))")
    assert atom_kind(Atom("cold", ("apple",)), {"cold"}) is AtomKind.PREDICATE
    assert atom_kind(Atom("pick_up", ("apple",)), {"cold"}) is AtomKind.ACTION
    actions, predicates = split_atoms(f, {"cold"})
    assert actions == {Atom("pick_up", ("apple",))}
    assert predicates == {Atom("cold", ("apple",))}


def test_primitive_set_objects():
    @dataclass
    class Kitchen:
        arities: dict
        predicates: frozenset

    kitchen = Kitchen(PRIMITIVES, frozenset({"cold"}))
    assert check_against(parse("F cold(apple)"), kitchen) == ()
    assert len(check_against(parse("F boil(egg)"), kitchen)) == 1
