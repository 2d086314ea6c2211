"""An edited body run in the kitchen before it is stored, with the values of the action it was learnt from.

A library body is parametric (`put($what, pot)`); the entry's `example` ({"$what": "egg"}) fills it, library
verbs are expanded down to primitives, and the plan goes to a `PlanValidator` (the embedded THOR kitchen).
The caller first checks the body's lines with `body_check.body_problems`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from cook2ltl.domain.actions import Action, Parameter, PrimitiveSet
from cook2ltl.library.body_check import verb_finder
from cook2ltl.library.store import Library, LibraryEntry
from cook2ltl.reduce.body import bind, instantiate
from cook2ltl.reduce.reduction import LibraryVerb, expand
from cook2ltl.reduce.validation import CheckStatus

NO_EXAMPLE = ("not checked in the kitchen: the entry has no example values to fill its placeholders "
              "(it was learnt before cook2ltl kept them)")


@dataclass(frozen=True)
class Recheck:
    validation: CheckStatus
    problems: tuple[str, ...]  # the kitchen's messages ("line 2 put(egg, pot): …")


def live_verbs(library: Library, primitives: str) -> list[LibraryVerb]:
    """The library verbs a body in this primitive set may call."""
    return [LibraryVerb(e.verb, e.signature, e.body) for e in library.live(primitives)]


def example_action(entry: LibraryEntry) -> Action | None:
    """The action the entry was learnt from, rebuilt from its example values; None without them."""
    values = dict(entry.example)
    placeholders = bind(entry.signature, entry.signature)  # {"$what": "what", "$what2": "what", …}, in order
    if any(placeholder not in values for placeholder in placeholders):
        return None
    return Action(entry.verb, tuple(Parameter(category, values[placeholder], values[placeholder], values[placeholder])
                                    for placeholder, category in placeholders.items()))


def recheck(entry: LibraryEntry, body: str, primitives: PrimitiveSet, verbs: Sequence[LibraryVerb],
            validator) -> Recheck:
    """Run `body` for the entry's example action through `validator` (a reduce.validation.PlanValidator)."""
    action = example_action(entry)
    if action is None:
        return Recheck(CheckStatus.UNCHECKED, (NO_EXAMPLE,))
    calls = instantiate(body, dict(entry.example))
    plan = expand(calls, primitives, verb_finder(verbs, entry.verb, entry.signature)) if calls is not None else None
    if plan is None:  # body_problems lets through only bodies that expand: a caller that skipped it
        raise ValueError(f"the body of {entry.action} does not expand to primitives; check it with body_problems")
    validation = validator.validate(action, plan)
    return Recheck(validation.status, validation.messages())
