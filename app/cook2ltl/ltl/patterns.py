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

``all_of`` and ``any_of`` repeat the rest of the sequence after each part
(LTL has no past operators to say "both have happened" otherwise). The
hash-consed AST shares the repeats, so building, progressing and the DFA stay
linear, but the *printed* formula doubles with each such element in a row.
"""

from __future__ import annotations

from collections.abc import Callable
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
    return _chain(elements, _finish)(TRUE)


# The sequence is built right to left as continuations: ``k(guard)`` is what
# must hold from the current step for the remaining elements to be visited,
# with ``guard`` true at every step until the first of them is. Each element
# computes ``k(TRUE)`` of what follows it once, when it is built, so the
# work is linear and nothing recurses down a long recipe.
Continuation = Callable[[Formula], Formula]


def _finish(guard: Formula) -> Formula:
    return TRUE if guard is TRUE else Always(guard)


def _chain(elements: tuple[Element, ...], k: Continuation) -> Continuation:
    for element in reversed(_spliced(elements)):
        k = _element(element, k)
    return k


def _spliced(elements: tuple[Element, ...]) -> list[Element]:
    """The elements with the parts of each ``then`` in its place, however deep."""
    flat: list[Element] = []
    todo = list(reversed(elements))
    while todo:
        element = todo.pop()
        if isinstance(element, Then):
            todo.extend(reversed(element.parts))
        else:
            flat.append(element)
    return flat


@dataclass(frozen=True)
class _Avoiding:
    """What must hold once ``avoided`` are added to the guard, then ``k``.

    A run of avoided elements is one of these, not a continuation per element
    calling the next, so a recipe of many "do not …" steps nests no calls.
    """

    avoided: tuple[Formula, ...]
    k: Continuation

    def __call__(self, guard: Formula) -> Formula:
        return self.k(And(guard, *(Not(f) for f in self.avoided)))


def _element(element: Element, k: Continuation) -> Continuation:
    match element:
        case Avoid(formula=f):
            if isinstance(k, _Avoiding):
                return _Avoiding((f, *k.avoided), k.k)
            return _Avoiding((f,), k)
        case AllOf(parts=parts):
            # Each part followed by the rest: the rest then comes after all parts.
            branches = [_chain((p,), k) for p in parts]
            return lambda guard: And(*(b(guard) for b in branches))
        case AnyOf(parts=parts):
            branches = [_chain((p,), k) for p in parts]
            return lambda guard: Or(*(b(guard) for b in branches))
        case HoldUntil(hold=hold, goal=goal):
            target = Until(hold, And(goal, k(TRUE)))
            return lambda guard: _reach(target, guard)
        case Formula():
            target = And(element, k(TRUE))
            return lambda guard: _reach(target, guard)
    raise TypeError(f"not a sequence element: {element!r}")


def _reach(target: Formula, guard: Formula) -> Formula:
    return Eventually(target) if guard is TRUE else Until(guard, target)
