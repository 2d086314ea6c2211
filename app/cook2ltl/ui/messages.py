"""Typed messages that thread workers post to their screen: progress, results, and the end of a run.

Workers never touch widgets; they post these dataclasses (`post_message` is thread-safe) and the screen draws
them. They stay on the screen (no bubbling) except `TranslationDone`, which the app keeps for the Rollout screen;
a newer `WorkProgress` replaces one still waiting in the queue.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from textual.message import Message

if TYPE_CHECKING:
    from cook2ltl.assembly.planning import Plan
    from cook2ltl.assembly.trial import Trial
    from cook2ltl.domain.actions import PrimitiveSet
    from cook2ltl.domain.recipe import ParsedRecipe
    from cook2ltl.execution.executor import Attempt
    from cook2ltl.execution.rollout import TraceStep
    from cook2ltl.execution.tasks import Task
    from cook2ltl.library import LibraryEntry, Version
    from cook2ltl.library.recheck import Recheck
    from cook2ltl.library.versions import Review
    from cook2ltl.ltl.ast import Atom, Formula
    from cook2ltl.pipeline.records import ActionDone, StepResult, Translation
    from cook2ltl.pipeline.world_rollout import ActionRolled, Began, RecipeRollout, StepRun
    from cook2ltl.reduce.reduction import LibraryVerb


class ScreenMessage(Message):
    """For the screen whose worker posted it."""

    bubble = False


@dataclass
class WorkProgress(ScreenMessage):
    """The latest word on a running job; each replaces the one before (done/total None: no bar)."""

    text: str
    done: int | None = None
    total: int | None = None

    def can_replace(self, message: Message) -> bool:
        return isinstance(message, WorkProgress)  # a newer word supersedes one the screen has not drawn yet


@dataclass
class WorkNotice(ScreenMessage):
    """Something the user should know about a job that goes on (a notification, not the status line)."""

    text: str


class WorkStopped(ScreenMessage):
    """The job ended early because it was cancelled."""


# --- translation -----------------------------------------------------------------------------------------

@dataclass
class RecipeParsed(ScreenMessage):
    parsed: ParsedRecipe


@dataclass
class ActionReduced(ScreenMessage):
    event: ActionDone
    total: int


@dataclass
class StepTranslated(ScreenMessage):
    result: StepResult


@dataclass
class TranslationDone(Message):
    """Bubbles to the app, which keeps the translation for the Rollout screen, with the primitive set it was
    made with (recipe, ai2thor or a file: what its world model is read from)."""

    translation: Translation
    primitives: str = ""


# --- library ---------------------------------------------------------------------------------------------

@dataclass
class LibraryLoaded(ScreenMessage):
    """The entries a search found (None when the query could not be read: `problem` says why)."""

    entries: tuple[LibraryEntry, ...] | None
    select: int | None = None
    problem: str = ""


@dataclass
class EntryHistory(ScreenMessage):
    """Every body an entry had, and every approval and rejection of them."""

    entry_id: int
    versions: tuple[Version, ...]
    reviews: tuple[Review, ...]


@dataclass
class EditorReady(ScreenMessage):
    """What the entry editor checks a body against: the primitive set (None if it cannot be read) and verbs."""

    primitives: PrimitiveSet | None
    verbs: list[LibraryVerb]
    problem: str


@dataclass
class KitchenChecked(ScreenMessage):
    body: str
    check: Recheck


# --- rollout ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class ObjectState:
    """One object the rollout touched, as the kitchen reports it now."""

    name: str
    where: str
    state: str


@dataclass
class RolloutBegan(ScreenMessage):
    formula: Formula
    scene: str
    task: Task | None
    plan: Plan | None
    unobservable: tuple[Atom, ...]


@dataclass
class RolloutStepped(ScreenMessage):
    step: TraceStep
    objects: tuple[ObjectState, ...]


@dataclass
class RolloutRefused(ScreenMessage):
    attempt: Attempt


@dataclass
class RolloutDone(ScreenMessage):
    trial: Trial


# --- a recipe rolled out in the world model -------------------------------------------------------------

@dataclass
class RecipeRolloutBegan(ScreenMessage):
    began: Began
    title: str


@dataclass
class RecipeActionRolled(ScreenMessage):
    """An action's plan lines applied (or refused) where the recipe has got to."""

    rolled: ActionRolled


@dataclass
class RecipeStepRolled(ScreenMessage):
    run: StepRun


@dataclass
class RecipeRolloutDone(ScreenMessage):
    rollout: RecipeRollout
