"""What a translation produces, and the progress events `translate` yields on the way to it."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from typing import TYPE_CHECKING

from cook2ltl.domain.actions import Call, Reduction
from cook2ltl.domain.recipe import ParsedRecipe, Step
from cook2ltl.ltl.ast import Formula
from cook2ltl.reduce.validation import CheckStatus, Validation
from cook2ltl.world.check import PlanCheck

if TYPE_CHECKING:  # a type only: the records load without the library (sqlite_utils)
    from cook2ltl.library.reuse import Reuse


class Variant(StrEnum):
    AR_STAR = "AR*"
    AR = "AR"
    AR_LIBRARY = "AR+A"


@dataclass(frozen=True)
class ActionResult:
    frame_index: int
    reduction: Reduction  # the body as found or written, library verbs included
    plan: tuple[Call, ...]  # the same down to primitives; empty when there is no admissible plan
    validation: Validation | None = None  # the kitchen check of a new reduction
    attempts: tuple[Reduction, ...] = ()  # the model's other reductions of this action (failed, then repaired)
    # For a library hit: the entry's own kitchen check (passed, failed, unchecked) and problems, so a plan
    # that failed when it was learnt is never reused silently.
    entry_validation: CheckStatus | None = None
    entry_problems: tuple[str, ...] = ()
    check: PlanCheck | None = None  # the plan in the world model, where the recipe's earlier steps left it
    reuse: Reuse | None = None  # a library hit learnt for another verb or signature: which entry, and why


@dataclass(frozen=True)
class StepResult:
    step: Step
    actions: tuple[ActionResult, ...]
    formula: Formula
    problems: tuple[str, ...]


@dataclass(frozen=True)
class Stats:
    actions: int = 0
    primitive: int = 0
    library_hits: int = 0
    cross_reuses: int = 0  # of the library hits, entries learnt for another verb or signature (library.reuse)
    no_plan_hits: int = 0  # of the library hits, entries recording that the model wrote no admissible plan
    llm_calls: int = 0
    prompt_tokens: int = 0
    completion_tokens: int = 0
    llm_seconds: float = 0.0
    dropped_lines: int = 0
    new_entries: int = 0
    validated: int = 0  # new reductions that passed the kitchen check
    checked: int = 0  # new reductions the kitchen could check (passed or failed)
    repaired: int = 0  # of the validated, those that passed only after a repair
    repair_calls: int = 0  # model calls for repairs (not in llm_calls; their tokens and time are)
    grounded: int = 0  # actions checked in the world model
    reached: int = 0  # of those, the ones whose plan reaches the action's intended effect
    model_lines_applied: int = 0  # new reductions whose lines as the model wrote them all applied
    planner_lines: int = 0  # plan lines the planner wrote
    effect_calls: int = 0  # model calls writing the effect of a verb the verb-effect table lacks
    seconds: float = 0.0
    # Of `seconds`, where the time went besides the model's (llm_seconds): running plans in the kitchen, and
    # the world model's checks, completions, the recipe's start and the lines it allows while the model writes.
    kitchen_seconds: float = 0.0
    world_seconds: float = 0.0


@dataclass(frozen=True)
class Translation:
    primitives: str
    variant: Variant
    model: str
    steps: tuple[StepResult, ...]
    formula: Formula  # every step in sequence
    stats: Stats
    validating: bool = False  # whether new reductions were checked in the kitchen
    world_start: object | None = None  # the world model's state before the first step (a world.logic.State)
    world_binding: Mapping[str, str] = field(default_factory=dict)  # THOR: the objectId each name stands for
    skipped_verbs: tuple[str, ...] = ()  # why library verbs were not offered to the model (not identifiers)


@dataclass(frozen=True)
class Parsed:
    recipe: ParsedRecipe


@dataclass(frozen=True)
class TranslationStarted:
    steps: int
    actions: int


@dataclass(frozen=True)
class ActionDone:
    step_index: int
    result: ActionResult
    done: int  # actions finished so far


@dataclass(frozen=True)
class StepDone:
    result: StepResult


@dataclass(frozen=True)
class TranslationFinished:
    translation: Translation


TranslationEvent = Parsed | TranslationStarted | ActionDone | StepDone | TranslationFinished
