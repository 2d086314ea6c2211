"""A new reduction checked in the kitchen and, while it fails, written again with the failure as feedback.

The paper caches the model's first plan, and a wrong one then spoils every later use. Here each new plan
is validated first; a failing one goes back to the model, at most `repairs` times, with its problems as
comment lines under the header and the lines before the first failing one already written; the grammar
(still on) keeps the model from calling there what failed there (in every repair so far at that place).
Shown the whole failed plan, a greedy model copies it (measured: every repair of qwen2.5-coder-1.5b was
its failed plan again); forbidding only the exact failing call, it wrote the same verb with another object. The last
plan is kept either way: the caller caches it with its validation, so a plan that still fails is never
taken for a good one.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

from cook2ltl.domain.actions import Action, Call, PrimitiveSet, Reduction
from cook2ltl.reduce.llm import LanguageModel
from cook2ltl.reduce.prompt import Feedback
from cook2ltl.reduce.reduction import LibraryVerb, ReductionSettings, reduce_action
from cook2ltl.reduce.validation import PlanValidator, Validation


@dataclass(frozen=True)
class Checked:
    """The reduction kept, its plan down to primitives (empty if none is admissible), its validation (None
    when not validated), and the other reductions the model wrote for the action: plans that failed, or a
    repair with no admissible line."""

    reduction: Reduction
    plan: tuple[Call, ...]
    validation: Validation | None
    failed: tuple[Reduction, ...] = ()

    @property
    def model_calls(self) -> tuple[Reduction, ...]:
        """Every reduction the model wrote for this action."""
        return (*self.failed, self.reduction)

    @property
    def repaired(self) -> bool:
        return bool(self.failed) and self.validation is not None and self.validation.passed


def reduce_checked(action: Action, primitives: PrimitiveSet, library: Sequence[LibraryVerb], model: LanguageModel,
                   settings: ReductionSettings, expand: Callable[[tuple[Call, ...]], tuple[Call, ...] | None],
                   validator: PlanValidator | None, repairs: int) -> Checked:
    """Reduce `action` with the model, validate the plan, and repair it up to `repairs` times.

    A repair is tried only for a plan the kitchen checked and refused; a repair that writes no admissible
    plan ends the loop and the previous plan is kept (it has a plan and known problems).
    """
    reduction = reduce_action(action, primitives, library, model, settings)
    current = _checked(action, reduction, expand, validator)
    failed: list[Reduction] = []
    feedback = None
    while len(failed) < repairs and _repairable(current.validation):
        feedback = feedback_for(current.reduction.body, current.validation, expand, settings.max_lines, feedback)
        again = _checked(action, reduce_action(action, primitives, library, model, settings, feedback),
                         expand, validator)
        if not again.plan:
            return Checked(current.reduction, current.plan, current.validation, (*failed, again.reduction))
        failed.append(current.reduction)
        current = again
    return Checked(current.reduction, current.plan, current.validation, tuple(failed))


def feedback_for(body: tuple[Call, ...], validation: Validation,
                 expand: Callable[[tuple[Call, ...]], tuple[Call, ...] | None], max_lines: int,
                 previous: Feedback | None = None) -> Feedback:
    """Keep the body up to its first failing line and avoid that line's name there (with the names the last
    repair avoided at the same place); with only whole-plan problems (a goal state not reached at the end),
    keep the whole body so the model adds to it."""
    lines = [problem.line for problem in validation.problems if problem.line > 0]
    if not lines:
        return Feedback(validation.messages(), body if len(body) < max_lines else ())
    first, done = min(lines), 0
    for index, call in enumerate(body):  # plan lines count library verbs expanded; find the body line
        done += len(expand((call,)) or (call,))
        if done >= first:
            same_place = previous is not None and previous.kept == body[:index]
            avoided = (*previous.avoid, call.name) if same_place else (call.name,)
            return Feedback(validation.messages(), body[:index], tuple(dict.fromkeys(avoided)))
    return Feedback(validation.messages())


def _checked(action: Action, reduction: Reduction, expand, validator: PlanValidator | None) -> Checked:
    plan = expand(reduction.body) or ()
    validation = validator.validate(action, plan) if validator is not None and plan else None
    return Checked(reduction, plan, validation)


def _repairable(validation: Validation | None) -> bool:
    return validation is not None and validation.checked and not validation.passed
