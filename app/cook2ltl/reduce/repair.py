"""A new reduction checked in the kitchen and, while it fails, written again with the failure as feedback.

The paper caches the model's first plan, and a wrong one then spoils every later use. Here each new plan
is validated first; a failing one goes back to the model with the failed body and its problems as
comment lines in the prompt (the grammar still on), at most `repairs` times. The last plan is kept either
way: the caller caches it with its validation, so a plan that still fails is never taken for a good one.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

from cook2ltl.reduce.llm import LanguageModel
from cook2ltl.reduce.model import Action, Call, PrimitiveSet, Reduction
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
    while len(failed) < repairs and _repairable(current.validation):
        feedback = Feedback(current.reduction.body, current.validation.messages())
        again = _checked(action, reduce_action(action, primitives, library, model, settings, feedback),
                         expand, validator)
        if not again.plan:
            return Checked(current.reduction, current.plan, current.validation, (*failed, again.reduction))
        failed.append(current.reduction)
        current = again
    return Checked(current.reduction, current.plan, current.validation, tuple(failed))


def _checked(action: Action, reduction: Reduction, expand, validator: PlanValidator | None) -> Checked:
    plan = expand(reduction.body) or ()
    validation = validator.validate(action, plan) if validator is not None and plan else None
    return Checked(reduction, plan, validation)


def _repairable(validation: Validation | None) -> bool:
    return validation is not None and validation.checked and not validation.passed
