"""The core's generators (`pipeline.translator.run`, `assembly.trial.run_trial`,
`pipeline.world_rollout.roll_out_recipe`) as streams of typed messages.

A worker only forwards what these yield, so the translating and rolling out are testable without a screen;
cancellation reaches the core as the same `threading.Event` the core takes.
"""

from __future__ import annotations

import threading
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from textual.message import Message

from cook2ltl.domain.settings import TranslateSettings
from cook2ltl.reduce.llm import GenerationCancelled
from cook2ltl.ui.messages import (
    ActionReduced, ObjectState, RecipeActionRolled, RecipeParsed, RecipeRolloutBegan, RecipeRolloutDone,
    RecipeStepRolled, RolloutBegan, RolloutDone, RolloutRefused, RolloutStepped, StepTranslated, TranslationDone,
    WorkNotice, WorkProgress, WorkStopped,
)
from cook2ltl.ui.services import Services

if TYPE_CHECKING:
    from cook2ltl.execution.tasks import Task
    from cook2ltl.ltl.ast import Formula
    from cook2ltl.pipeline.records import Translation


@dataclass(frozen=True)
class TranslateRequest:
    text: str
    primitives: str  # recipe, ai2thor, or a TOML file
    variant: str  # a pipeline.records.Variant value
    model: str
    validate: bool = True  # run new reductions in the kitchen before caching them (repairing failures)
    approved_only: bool = False  # lab mode: reuse approved library entries only
    repairs: int = TranslateSettings.repairs  # times a plan the kitchen refuses goes back to the model
    ground: bool = TranslateSettings.ground  # plans decoded, checked and completed in the world model
    reuse: bool = TranslateSettings.reuse  # library entries reused across verbs of one table row and signatures


@dataclass(frozen=True)
class RolloutRequest:
    scene: str
    task: Task | None = None
    formula: Formula | None = None  # None: plan the task's instruction with Algorithm 1 first
    model: str = ""
    repairs: int = TranslateSettings.repairs  # as TranslateRequest's, when the instruction is planned


@dataclass(frozen=True)
class RecipeRolloutRequest:
    """A recipe rolled out in the world model: a finished translation as it is, else `translate` run first."""

    title: str
    primitives: str  # the set the translation is (or will be) made with: recipe, ai2thor, or a TOML file
    translation: Translation | None = None
    translate: TranslateRequest | None = None


def translation_feed(services: Services, request: TranslateRequest, cancel: threading.Event) -> Iterator[Message]:
    if not services.pipeline_lock.acquire(blocking=False):
        yield WorkProgress("waiting for the models: a rollout is planning …")
        services.pipeline_lock.acquire()
    try:
        yield from _translating(services, request, cancel)
    except GenerationCancelled:  # stopped mid-plan: nothing of that plan was cached
        yield WorkStopped()
    finally:
        services.pipeline_lock.release()


def _translating(services: Services, request: TranslateRequest, cancel: threading.Event) -> Iterator[Message]:
    # startup: the app opens before the pipeline loads; the first run in a worker loads it
    from cook2ltl.assembly.translators import TranslateOptions, build_translator
    from cook2ltl.pipeline.records import ActionDone, Parsed, StepDone, TranslationFinished, TranslationStarted, Variant
    from cook2ltl.pipeline.translator import run
    from cook2ltl.reduce.primitives import load_primitives

    variant = Variant(request.variant)
    primitives = load_primitives(request.primitives)
    yield WorkProgress("loading the parsing models …")
    spans, dependencies = services.spans(), services.dependencies()
    library = services.library() if variant == Variant.AR_LIBRARY else None
    # The check box turns the kitchen check off; on, it checks where the rule says it helps, as the CLI does.
    options = TranslateOptions(variant, check=None if request.validate else False, repairs=request.repairs,
                               approved_only=request.approved_only, ground=request.ground, reuse=request.reuse)
    notices: list[str] = []
    translator = build_translator(primitives, services.model(request.model, cancel), library, options,
                                  services.validator, notices.append)
    for notice in notices:
        yield WorkNotice(notice)
    yield WorkProgress("parsing (the span model loads on first use) …")
    total = 0
    for event in run(request.text, spans, dependencies, translator, cancel):
        if isinstance(event, Parsed):
            yield RecipeParsed(event.recipe)
        elif isinstance(event, TranslationStarted):
            total = event.actions
            yield WorkProgress(f"reducing {total} actions with {request.model} …", 0, total)
        elif isinstance(event, ActionDone):
            yield ActionReduced(event, total)
            reduction = event.result.reduction
            yield WorkProgress(f"{reduction.action.text()} ({reduction.source.value})", event.done, total)
        elif isinstance(event, StepDone):
            yield StepTranslated(event.result)
        elif isinstance(event, TranslationFinished):
            yield TranslationDone(event.translation, request.primitives)
            return
    yield WorkStopped()


def rollout_feed(services: Services, request: RolloutRequest, cancel: threading.Event) -> Iterator[Message]:
    # startup: the app opens before the pipeline loads; the first run in a worker loads it
    from cook2ltl.assembly.trial import TrialDone, run_trial
    from cook2ltl.execution.rollout import ActionRefused, RolloutStarted, Stepped

    task, plan, formula = request.task, None, request.formula
    if formula is None:
        yield WorkProgress(f"planning “{task.instruction}” with {request.model} …")
        with services.pipeline_lock:
            try:
                plan = _planner(services, request, cancel).plan(task.instruction, request.scene)
            except GenerationCancelled:
                plan = None
        if plan is None or cancel.is_set():
            yield WorkStopped()
            return
        formula = plan.formula
    yield WorkProgress(f"starting the kitchen ({request.scene}) …")
    with services.kitchen_lock:
        kitchen = services.kitchen(request.scene)
        touched: dict[str, None] = {}
        for event in run_trial(kitchen, formula, request.scene, task, plan, cancel=cancel):
            if isinstance(event, RolloutStarted):
                yield RolloutBegan(event.formula, event.scene, task, plan, event.unobservable)
                yield WorkProgress("rolling out …")
            elif isinstance(event, Stepped):
                touched.update(dict.fromkeys(_object_ids(event.step.attempt.calls)))
                yield RolloutStepped(event.step, object_states(kitchen.last_event.metadata["objects"], touched))
            elif isinstance(event, ActionRefused):
                yield RolloutRefused(event.attempt)
            elif isinstance(event, TrialDone):
                yield RolloutDone(event.trial)


def recipe_rollout_feed(services: Services, request: RecipeRolloutRequest, cancel: threading.Event
                        ) -> Iterator[Message]:
    # startup: the app opens before the pipeline loads; the first run in a worker loads it
    from cook2ltl.pipeline.world_rollout import ActionRolled, Began, RecipeRolledOut, StepRolled, roll_out_recipe
    from cook2ltl.reduce.primitives import load_primitives

    translation = request.translation
    if translation is None:
        for message in translation_feed(services, request.translate, cancel):
            if isinstance(message, TranslationDone):
                translation = message.translation
            # the status only: the Translate screen and its export keep showing their own translation
            if isinstance(message, (WorkProgress, WorkNotice, WorkStopped)):
                yield message
        if translation is None:
            return  # stopped: translation_feed said so
    total = 0
    for event in roll_out_recipe(translation, load_primitives(request.primitives), cancel=cancel):
        if isinstance(event, Began):
            total = event.actions
            yield RecipeRolloutBegan(event, request.title)
        elif isinstance(event, ActionRolled):
            yield RecipeActionRolled(event)
            yield WorkProgress(f"rolling out {event.run.result.reduction.action.text()}", event.done, total)
        elif isinstance(event, StepRolled):
            yield RecipeStepRolled(event.run)
        elif isinstance(event, RecipeRolledOut):
            yield RecipeRolloutDone(event.rollout)
            return
    yield WorkStopped()


def _planner(services: Services, request: RolloutRequest, cancel: threading.Event):
    # startup: the app opens before the pipeline loads; the first run in a worker loads it
    from cook2ltl.assembly.planning import PRIMITIVES, TaskPlanner, ignore_notice
    from cook2ltl.assembly.translators import TranslateOptions, build_translator
    from cook2ltl.reduce.primitives import load_primitives

    # New reductions are checked and repaired before they are cached, as when translating; the planner grounds
    # each plan in the kitchen it runs in.
    options = TranslateOptions(repairs=request.repairs, ground=False)
    translator = build_translator(load_primitives(PRIMITIVES), services.model(request.model, cancel),
                                  services.library(), options, services.validator, ignore_notice)
    return TaskPlanner(translator, services.spans(), services.dependencies())


def _object_ids(calls) -> list[str]:
    return [call.action["objectId"] for call in calls if "objectId" in call.action]


def object_states(objects: Sequence[Mapping[str, Any]], ids: Sequence[str]) -> tuple[ObjectState, ...]:
    """The objects a rollout touched, in the order it first touched them, as the kitchen sees them now."""
    by_id = {o["objectId"]: o for o in objects}
    states = []
    for object_id in ids:
        found = by_id.get(object_id)
        name = object_id.split("|")[0]
        if found is None:
            states.append(ObjectState(name, "", "gone (sliced or broken into pieces)"))
            continue
        parents = found.get("parentReceptacles") or []
        where = "in hand" if found.get("isPickedUp") else (parents[0].split("|")[0] if parents else "")
        states.append(ObjectState(name, where, ", ".join(_flags(found)) or "—"))
    return tuple(states)


def _flags(o: Mapping[str, Any]) -> list[str]:
    flags = []
    if o.get("openable"):
        flags.append("open" if o.get("isOpen") else "closed")
    if o.get("toggleable"):
        flags.append("on" if o.get("isToggled") else "off")
    if o.get("temperature") in ("Hot", "Cold"):
        flags.append(o["temperature"].lower())
    named = {"isSliced": "sliced", "isCooked": "cooked", "isBroken": "broken", "isUsedUp": "used up",
             "isDirty": "dirty"}
    flags += [word for key, word in named.items() if o.get(key)]
    if o.get("isFilledWithLiquid"):
        flags.append(f"filled with {o.get('fillLiquid') or 'liquid'}")
    return flags
