"""Typed messages that thread workers post to their screen: progress, results, and the end of a run.

Workers never touch widgets; they post these (`post_message` is thread-safe) and the screen draws them. They
stay on the screen (no bubbling) except `TranslationDone`, which the app keeps for the Rollout screen.
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


class WorkProgress(ScreenMessage):
    """The latest word on a running job; each replaces the one before (done/total None: no bar)."""

    def __init__(self, text: str, done: int | None = None, total: int | None = None) -> None:
        super().__init__()
        self.text, self.done, self.total = text, done, total


class WorkNotice(ScreenMessage):
    """Something the user should know about a job that goes on (a notification, not the status line)."""

    def __init__(self, text: str) -> None:
        super().__init__()
        self.text = text


class WorkStopped(ScreenMessage):
    """The job ended early because it was cancelled."""


# --- translation -----------------------------------------------------------------------------------------

class RecipeParsed(ScreenMessage):
    def __init__(self, parsed: ParsedRecipe) -> None:
        super().__init__()
        self.parsed = parsed


class ActionReduced(ScreenMessage):
    def __init__(self, event: ActionDone, total: int) -> None:
        super().__init__()
        self.event, self.total = event, total


class StepTranslated(ScreenMessage):
    def __init__(self, result: StepResult) -> None:
        super().__init__()
        self.result = result


class TranslationDone(Message):
    """Bubbles to the app, which keeps the translation for the Rollout screen, with the primitive set it was
    made with (recipe, ai2thor or a file: what its world model is read from)."""

    def __init__(self, translation: Translation, primitives: str = "") -> None:
        super().__init__()
        self.translation, self.primitives = translation, primitives


# --- library ---------------------------------------------------------------------------------------------

class LibraryLoaded(ScreenMessage):
    """The entries a search found (None when the query could not be read: `problem` says why)."""

    def __init__(self, entries: tuple[LibraryEntry, ...] | None, select: int | None = None,
                 problem: str = "") -> None:
        super().__init__()
        self.entries, self.select, self.problem = entries, select, problem


class EntryHistory(ScreenMessage):
    """Every body an entry had, and every approval and rejection of them."""

    def __init__(self, entry_id: int, versions: tuple[Version, ...], reviews: tuple[Review, ...]) -> None:
        super().__init__()
        self.entry_id, self.versions, self.reviews = entry_id, versions, reviews


class EditorReady(ScreenMessage):
    """What the entry editor checks a body against: the primitive set (None if it cannot be read) and verbs."""

    def __init__(self, primitives: PrimitiveSet | None, verbs: list[LibraryVerb], problem: str) -> None:
        super().__init__()
        self.primitives, self.verbs, self.problem = primitives, verbs, problem


class KitchenChecked(ScreenMessage):
    def __init__(self, body: str, check: Recheck) -> None:
        super().__init__()
        self.body, self.check = body, check


# --- rollout ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class ObjectState:
    """One object the rollout touched, as the kitchen reports it now."""

    name: str
    where: str
    state: str


class RolloutBegan(ScreenMessage):
    def __init__(self, formula: Formula, scene: str, task: Task | None, plan: Plan | None,
                 unobservable: tuple[Atom, ...]) -> None:
        super().__init__()
        self.formula, self.scene, self.task, self.plan, self.unobservable = formula, scene, task, plan, unobservable


class RolloutStepped(ScreenMessage):
    def __init__(self, step: TraceStep, objects: tuple[ObjectState, ...]) -> None:
        super().__init__()
        self.step, self.objects = step, objects


class RolloutRefused(ScreenMessage):
    def __init__(self, attempt: Attempt) -> None:
        super().__init__()
        self.attempt = attempt


class RolloutDone(ScreenMessage):
    def __init__(self, trial: Trial) -> None:
        super().__init__()
        self.trial = trial


# --- a recipe rolled out in the world model -------------------------------------------------------------

class RecipeRolloutBegan(ScreenMessage):
    def __init__(self, began: Began, title: str) -> None:
        super().__init__()
        self.began, self.title = began, title


class RecipeActionRolled(ScreenMessage):
    """An action's plan lines applied (or refused) where the recipe has got to."""

    def __init__(self, rolled: ActionRolled) -> None:
        super().__init__()
        self.rolled = rolled


class RecipeStepRolled(ScreenMessage):
    def __init__(self, run: StepRun) -> None:
        super().__init__()
        self.run = run


class RecipeRolloutDone(ScreenMessage):
    def __init__(self, rollout: RecipeRollout) -> None:
        super().__init__()
        self.rollout = rollout
