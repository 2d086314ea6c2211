"""The sequenced-visit pattern the translator builds recipes with.

``sequenced_visit(a1, a2, …, an)`` is the paper's ``◇(a1 ∧ ◇(a2 ∧ … ◇an))``:
the steps happen in this order, other actions may come in between. Each
element is an already-built formula (usually one action) or a combinator:

* ``all_of(x, y)`` — both are visited, in any order, before the sequence goes on;
* ``any_of(x, y)`` — at least one is;
* ``avoid(f)`` — ``f`` holds at no step from here until the next element is
  visited (to the end of the trace if nothing follows);
* ``hold_until(stir, thickened)`` — from some point on, ``stir`` at every
  step until ``thickened``; the sequence goes on from there;
* ``then(x, y)`` — a sub-sequence, e.g. the primitive plan of one high-level
  action.

Why ``hold_until`` nests the Until inside the sequence: next to an action,
as in ``◇(a ∧ (stir 𝒰 thickened))``, it would have to start at the very step
``a`` is done, where ``stir`` is not (one action per step), so it is violated
by that action unless ``thickened`` already holds. Inside, as
``◇(a ∧ ◇(stir 𝒰 thickened))``, the stirring starts after ``a``.

Like the paper's pattern, a visit does not need a step of its own: visiting
the same action twice in a row is met by a single occurrence.
"""

from __future__ import annotations

from dataclasses import dataclass

from cook2ltl.ltl.ast import TRUE, Always, And, Eventually, Formula, Not, Or, Until


@dataclass(frozen=True)
class AllOf:
    parts: tuple[Element, ...]


@dataclass(frozen=True)
class AnyOf:
    parts: tuple[Element, ...]


@dataclass(frozen=True)
class Avoid:
    formula: Formula


@dataclass(frozen=True)
class HoldUntil:
    hold: Formula
    goal: Formula


@dataclass(frozen=True)
class Then:
    parts: tuple[Element, ...]


Element = Formula | AllOf | AnyOf | Avoid | HoldUntil | Then


def all_of(*parts: Element) -> AllOf:
    return AllOf(parts)


def any_of(*parts: Element) -> AnyOf:
    return AnyOf(parts)


def avoid(formula: Formula) -> Avoid:
    return Avoid(formula)


def hold_until(hold: Formula, goal: Formula) -> HoldUntil:
    return HoldUntil(hold, goal)


def then(*parts: Element) -> Then:
    return Then(parts)


def sequenced_visit(*elements: Element) -> Formula:
    """``◇(ψ1 ∧ ◇(ψ2 ∧ … ◇ψn))`` for the elements ψ1 … ψn (combinators expanded)."""
    return _visit(elements, TRUE)


def _visit(elements: tuple[Element, ...], guard: Formula) -> Formula:
    """What must hold from the current step: the elements in order, and
    ``guard`` at every step until the first of them is visited."""
    if not elements:
        return TRUE if guard is TRUE else Always(guard)
    first, rest = elements[0], elements[1:]
    match first:
        case Then(parts=parts):
            return _visit(parts + rest, guard)
        case Avoid(formula=f):
            return _visit(rest, And(guard, Not(f)))
        case AllOf(parts=parts):
            # Each part followed by the rest: the rest then comes after all parts.
            return And(*(_visit((p, *rest), guard) for p in parts))
        case AnyOf(parts=parts):
            return Or(*(_visit((p, *rest), guard) for p in parts))
        case HoldUntil(hold=hold, goal=goal):
            return _reach(Until(hold, And(goal, _visit(rest, TRUE))), guard)
        case Formula():
            return _reach(And(first, _visit(rest, TRUE)), guard)
    raise TypeError(f"not a sequence element: {first!r}")


def _reach(target: Formula, guard: Formula) -> Formula:
    return Eventually(target) if guard is TRUE else Until(guard, target)
