"""f_LTL: plans and steps as sequenced-visit formulas, ◇(ψ1 ∧ ◇(ψ2 ∧ … ◇ψn)), with ∧ ∨ ¬ 𝒰.

* a plan (the body of one action) is a sub-sequence of its calls; `wait(x == s)` is `wait 𝒰 s(x)`
  inside the sequence: the robot waits at every step until the state holds, then the plan goes on;
* a step is the sequence of its actions; actions joined by "or" are alternatives (∨);
* objects joined by "and" in a primitive action are all visited, in any order (∧);
* a negated action ("do not overmix") is avoided until the next action (¬).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from cook2ltl.domain.actions import TIMER, WAIT, Action, Call, Primitive, PrimitiveSet
from cook2ltl.domain.recipe import Connective
from cook2ltl.ltl.ast import TRUE, Atom, Formula
from cook2ltl.ltl.atoms import AtomProblem, check_atoms
from cook2ltl.ltl.patterns import Element, all_of, any_of, avoid, hold_until, sequenced_visit, then

ELAPSED = "elapsed"  # the predicate of a duration: wait(timer == 30_minutes) waits for elapsed(30_minutes)
# Time phrases that bound an action: "until thick", "for 5 minutes", "once melted".
CONDITION_MARKERS = frozenset({"until", "till", "for", "once", "when"})


@dataclass(frozen=True)
class Part:
    """One action of a step as a sequence element, and how it joins the next one."""

    element: Element
    negated: bool = False


def condition_atom(subject: str, state: str) -> Atom:
    return Atom(ELAPSED, (state,)) if subject == TIMER else Atom(state, (subject,))


def call_atom(call: Call, primitives: PrimitiveSet) -> Formula:
    """A plan line's action in a formula: a wait is the bare `wait` atom (its condition is the Until's goal),
    ⊤ when the set has no wait to hold."""
    if call.is_wait:
        return Atom(WAIT) if primitives.get(WAIT) else TRUE
    return Atom(call.name, call.args)


def plan_element(calls: tuple[Call, ...], primitives: PrimitiveSet) -> Element:
    """The primitive calls of a plan, in order; each wait becomes an Until inside the sequence."""
    elements = [hold_until(call_atom(call, primitives), condition_atom(*call.args)) if call.is_wait
                else call_atom(call, primitives) for call in calls]
    return elements[0] if len(elements) == 1 else then(*elements)


def direct_calls(action: Action, primitive: Primitive) -> tuple[Call, ...] | None:
    """The action as calls of its own primitive, one per object ("put milk and salt into a pan"), when its
    objects fill the primitive's parameters; None when they do not and the action needs a reduction."""
    if primitive.object_arity != len(primitive.params):  # wait needs a condition, which a frame does not give
        return None
    whats = [p.value for p in action.parameters if p.category == "what"]
    wheres = [p.value for p in action.parameters if p.category == "where"]
    if primitive.object_arity == 0:
        return (Call(primitive.name, ()),)
    if primitive.object_arity == 1 and whats:
        return tuple(Call(primitive.name, (what,)) for what in whats)
    if primitive.object_arity == 2 and whats and len(wheres) == 1:
        return tuple(Call(primitive.name, (what, wheres[0])) for what in whats)
    return None


def direct_element(action: Action, calls: tuple[Call, ...], primitives: PrimitiveSet) -> Element:
    """A primitive action with its objects all visited (∧), held until its time condition if it has one."""
    atoms = [Atom(call.name, call.args) for call in calls]
    element: Element = atoms[0] if len(atoms) == 1 else all_of(*atoms)
    condition = time_condition(action)
    if condition is None:
        return element
    if len(atoms) == 1:
        return hold_until(atoms[0], condition)  # "stir the soup until thick": stir 𝒰 thick(soup)
    return then(element, hold_until(Atom(WAIT) if primitives.get(WAIT) else TRUE, condition))


def time_condition(action: Action) -> Atom | None:
    """"until thick" → thick(soup); "for 5 minutes" → elapsed(5_minutes); other times bound nothing."""
    subject = next((p.value for p in action.parameters if p.category == "what"), None)
    for parameter in action.parameters:
        if parameter.category != "time":
            continue
        if parameter.value[:1].isdigit():
            return condition_atom(TIMER, parameter.value)
        first = parameter.text.split()[0].lower() if parameter.text.split() else ""
        if first in CONDITION_MARKERS and subject:
            return Atom(parameter.value, (subject,))
    return None


def alternatives(elements: list[Element]) -> Element:
    return elements[0] if len(elements) == 1 else any_of(*elements)


def step_element(parts: list[Part | None], links: tuple[Connective, ...]) -> Element:
    """Actions in sequence; a run of actions joined by "or" is one alternative; negated ones are avoided.

    `parts` follow the step's frames (None for one that has no plan) and `links[i]` joins frames i and i + 1.
    """
    groups: list[list[Part | None]] = []
    for index, part in enumerate(parts):
        if index and index - 1 < len(links) and links[index - 1] == Connective.OR:
            groups[-1].append(part)
        else:
            groups.append([part])
    elements = [_group_element([p for p in group if p is not None]) for group in groups if any(group)]
    return elements[0] if len(elements) == 1 else then(*elements)


def _group_element(group: list[Part]) -> Element:
    elements = [_avoided(part.element) if part.negated else part.element for part in group]
    return elements[0] if len(elements) == 1 else any_of(*elements)


def _avoided(element: Element) -> Element:
    return avoid(element if isinstance(element, Formula) else sequenced_visit(element))


def atom_arities(primitives: PrimitiveSet, predicates: Mapping[str, int]) -> dict[str, int]:
    """Arities of every admissible atom: primitives (a wait's condition is a predicate of its own, so the
    wait atom takes no argument) and the state predicates."""
    return {**predicates, **{p.name: p.object_arity for p in primitives.primitives}}


def check(formula: Formula, primitives: PrimitiveSet, predicates: Mapping[str, int]) -> tuple[AtomProblem, ...]:
    return check_atoms(formula, atom_arities(primitives, predicates), predicates.keys())
