"""An edited library body run in the kitchen before it is stored: the one rule `cook2ltl library edit` and the
app's entry editor share (the caller has already checked the body's lines with `body_check.body_problems`)."""

from __future__ import annotations

from collections.abc import Callable

from cook2ltl.domain.actions import PrimitiveSet
from cook2ltl.execution.kitchen_check import unsupported
from cook2ltl.library.entry import LibraryEntry
from cook2ltl.library.recheck import Recheck, recheck
from cook2ltl.reduce.reduction import LibraryVerb
from cook2ltl.reduce.validation import CheckStatus, PlanValidator


def edited_body_check(entry: LibraryEntry, body: str, primitives: PrimitiveSet, verbs: list[LibraryVerb],
                      kitchen: Callable[[], PlanValidator]) -> Recheck:
    """The body's kitchen check with the values of the action it was learnt from; unchecked, saying why, when the
    kitchen has no action for some primitive of the set (`kitchen` is then never started)."""
    missing = unsupported(primitives)
    if missing:
        return Recheck(CheckStatus.UNCHECKED,
                       (f"not checked in the kitchen: it has no action for {', '.join(missing)}",))
    return recheck(entry, body, primitives, verbs, kitchen())
