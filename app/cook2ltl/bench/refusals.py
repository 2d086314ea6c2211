"""Why the kitchen refused the new plans of a Table I variant: each refused plan's first problem, by kind.

A kind is the problem with the call's own arguments left out, so "put(meat, pot): the agent holds nothing; the
plan must pick up meat first" and the same for chicken count together.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Iterable

from cook2ltl.domain.actions import Source
from cook2ltl.reduce.validation import LineProblem

SHOWN = 5  # kinds per variant under the table


def problem_kind(problem: LineProblem) -> str:
    name, _, inside = problem.call.partition("(")
    arguments = [a for a in re.split(r", | == ", inside.rstrip(")")) if a]
    message = problem.message
    for argument in sorted(arguments, key=len, reverse=True):
        message = re.sub(rf"\b{re.escape(argument)}\b", "…", message)
    return f"{name}: {message}"


def refusals(translations: Iterable) -> dict[str, int]:
    """Kinds of first problems of the new reductions the kitchen checked and refused, most common first."""
    kinds = Counter(problem_kind(result.validation.problems[0])
                    for translation in translations for step in translation.steps for result in step.actions
                    if result.reduction.source == Source.LLM and result.validation is not None
                    and result.validation.checked and not result.validation.passed and result.validation.problems)
    return dict(kinds.most_common())


def refusals_note(label: str, found: dict[str, int]) -> str:
    if not found:
        return ""
    shown = "; ".join(f"{kind} ({count})" for kind, count in list(found.items())[:SHOWN])
    return f"{label}, plans refused by the kitchen ({sum(found.values())}), by first problem: {shown}.\n"
