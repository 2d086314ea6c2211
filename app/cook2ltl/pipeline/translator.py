"""Algorithm 1 of the paper: parsed steps → actions → reductions (primitive, library or model) → LTL.

`translate` is a generator of progress events, so the command line draws a bar from it and a UI worker
can forward them; a `threading.Event` stops it between two actions.

Variants of the paper's ablation: AR* reduces every action with the model; AR passes the primitives
through; AR+𝔸 (the default) also looks the action library up first and caches every new reduction.

With a `validator`, every new reduction is first run in the kitchen; a failing one is written again with
the failure as feedback, at most `repairs` times, and cached with its validation (passed, failed or
unchecked) as a pending entry: only a reviewer approves. Library hits are not validated again: the entry
was checked when it was learnt and carries that result, and reuse must stay a lookup (the paper's point);
a lab that wants only reviewed plans sets `approved_only`. A reduction with no admissible plan is cached too,
as an entry with an empty body: the action is then not sent to the model again (until a reviewer rejects
the entry), and the lab sees which body to write.

An action whose exact key (verb, signature) has no usable entry may be served by an entry learnt for a verb the
verb-effect table reads as the same action, or for another signature (`library.reuse`; `reuse` False: exact
keys only). It is a library hit that says where it came from, and nothing is learnt under the new key.
"""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass, replace
from typing import Iterator

from cook2ltl.domain.actions import Action, Call, PrimitiveSet, Reduction, Source
from cook2ltl.domain.recipe import ParsedRecipe
from cook2ltl.formulas.formula import (
    ELAPSED, Part, alternatives, check, direct_calls, direct_element, plan_element, step_element,
)
from cook2ltl.library.reuse import Fit, reuses
from cook2ltl.library.store import Library, LibraryEntry
from cook2ltl.ltl.ast import Formula
from cook2ltl.ltl.patterns import Element, sequenced_visit
from cook2ltl.parse.backends import DependencyParser, SpanExtractor
from cook2ltl.parse.recipe import parse_recipe
from cook2ltl.pipeline.claims import Claims
from cook2ltl.pipeline.records import (
    ActionDone, ActionResult, Parsed, Stats, StepDone, StepResult, Translation, TranslationEvent,
    TranslationFinished, TranslationStarted, Variant,
)
from cook2ltl.reduce.action import actions_of, known_objects
from cook2ltl.reduce.body import instantiate, parametrize, placeholders
from cook2ltl.reduce.grounded import reduce_in_world
from cook2ltl.reduce.intents import Intents
from cook2ltl.reduce.llm import LanguageModel
from cook2ltl.reduce.reduction import LibraryVerb, ReductionSettings, expand, offered_verbs
from cook2ltl.reduce.repair import Checked, reduce_checked
from cook2ltl.reduce.validation import CheckStatus, LineProblem, PlanValidator, RecipeSoFar, Validation
from cook2ltl.world.check import Grounding, PlanCheck, check_plan
from cook2ltl.world.effects import cast, known_verb, table_effect, template_text
from cook2ltl.world.planner import all_reached

NO_PLAN_PROBLEM = "the model wrote no admissible plan; write its body with `cook2ltl library edit`"


@dataclass(frozen=True)
class Translator:
    primitives: PrimitiveSet
    model: LanguageModel
    library: Library | None = None  # needed by AR+𝔸 only
    variant: Variant = Variant.AR_LIBRARY
    settings: ReductionSettings = ReductionSettings()
    validator: PlanValidator | None = None  # checks new reductions in the kitchen before they are cached
    repairs: int = 2  # how many times a plan that fails the check is written again
    approved_only: bool = False  # lab mode: reuse approved library entries only
    grounding: Grounding | None = None  # the world model every plan is checked and completed in (None: off)
    reuse: bool = True  # reuse an entry across verbs of one table row and across signatures (False: exact keys)
    claims: Claims | None = None  # keys being reduced by translations running beside this one


def run(text: str, spans: SpanExtractor, dependencies: DependencyParser, translator: Translator,
        cancel: threading.Event | None = None) -> Iterator[TranslationEvent]:
    """The whole of Algorithm 1 on a recipe's text: preprocessing and parsing, then `translate`."""
    parsed = parse_recipe(text, spans, dependencies)
    yield Parsed(parsed)
    yield from translate(parsed, translator, cancel)


def translate(parsed: ParsedRecipe, translator: Translator, cancel: threading.Event | None = None
              ) -> Iterator[TranslationEvent]:
    started = time.perf_counter()
    state = _Run(translator)
    state.start(parsed)
    total = sum(len(actions_of(frame)) for step in parsed.steps for frame in step.frames)
    yield TranslationStarted(len(parsed.steps), total)
    steps, elements, done = [], [], 0
    for step in parsed.steps:
        results, parts = [], []
        for frame_index, frame in enumerate(step.frames):
            options = []
            for action in actions_of(frame):
                if cancel is not None and cancel.is_set():
                    return
                kitchen = state.world_state
                result, element = state.action(frame_index, action)
                if frame.negated:  # checked where the recipe is, but never done: the kitchen stays as it was
                    state.world_state = kitchen
                else:
                    state.ran.extend(result.plan)
                results.append(result)
                done += 1
                yield ActionDone(step.index, result, done)
                if element is not None:
                    options.append(element)
            parts.append(Part(alternatives(options), frame.negated) if options else None)
        element = step_element(parts, step.links)
        formula = sequenced_visit(element)
        problems = state.problems(results, formula)
        elements.append(element)
        steps.append(StepResult(step, tuple(results), formula, problems))
        yield StepDone(steps[-1])
    written = state.intents.written if state.intents else []
    stats = replace(state.stats, seconds=time.perf_counter() - started, effect_calls=len(written),
                    llm_seconds=state.stats.llm_seconds + sum(usage.seconds for usage in written))
    yield TranslationFinished(Translation(translator.primitives.name, translator.variant, translator.model.name,
                               tuple(steps), sequenced_visit(*elements), stats, translator.validator is not None,
                               state.world_start, state.world_binding, state.skipped_verbs))


def world_validation(grounded: PlanCheck) -> Validation:
    """The world model's verdict where no kitchen checks the plan: the plan kept applies by construction, so it
    passes when it reaches the action's intended effect."""
    problems = tuple(LineProblem(0, "world model", problem) for problem in grounded.problems)
    return Validation(grounded.effect_reached, problems, "world model", 0.0)


class _Run:
    """The state of one translation: the library's live verbs and the running counts."""

    def __init__(self, translator: Translator) -> None:
        self.stats = Stats()
        self.t = translator if translator.validator is None else replace(
            translator, validator=_TimedCheck(translator.validator, self._count))
        self.uses_library = translator.variant == Variant.AR_LIBRARY
        if self.uses_library and translator.library is None:
            raise ValueError("the AR+A variant needs a library")
        self.verbs: list[LibraryVerb] = []
        self.skipped_verbs: tuple[str, ...] = ()
        self.world_state = self.world_start = None  # the world model's state: where the recipe has got to
        self.world_binding: dict[str, str] = {}  # in a THOR kitchen, the objectId each name stands for
        self.scene = ""  # that THOR kitchen's scene
        self.ran: list[Call] = []  # the lines of the recipe's actions so far, as a kitchen check replays them
        self.intents = None if translator.grounding is None else Intents(
            translator.grounding.world, translator.model if hasattr(translator.model, "complete_lines") else None)
        self._refresh()

    def action(self, frame_index: int, action: Action) -> tuple[ActionResult, Element | None]:
        primitives = self.t.primitives
        self._count(actions=1)
        action = action if self.world_state is None else known_objects(action, self.world_state.objects)
        primitive = primitives.get(action.verb)
        if primitive is not None and self.t.variant != Variant.AR_STAR:
            calls = direct_calls(action, primitive)
            if calls is not None:
                effect = self._effect(action, write=False)
                if done := self._needless(frame_index, action, effect):
                    return done, None
                self._count(primitive=1)
                grounded = self._ground(action, calls, "recipe", effect)
                plan = grounded.plan if grounded else calls
                result = ActionResult(frame_index, Reduction(action, calls, Source.PRIMITIVE), plan, check=grounded)
                element = direct_element(action, calls, primitives) if plan == calls else plan_element(plan, primitives)
                return result, element
        if not self.uses_library:
            return self._from_model(frame_index, action, None)
        # What is claimed is the action, not the key: another verb of its table row may be learnt meanwhile
        # and serve it (a reuse), so a recipe beside this one reducing any of them is waited for.
        key = (primitives.name, (known_verb(action.verb) or action.verb) if self.t.reuse else action.verb,
               () if self.t.reuse else action.signature)
        done, stale = self._from_library(frame_index, action)
        while done is None and self.t.claims is not None and not self.t.claims.take(key):
            done, stale = self._from_library(frame_index, action)  # learnt meanwhile beside us: look again
        if done is not None:
            return done
        try:
            return self._from_model(frame_index, action, stale)
        finally:
            if self.t.claims is not None:
                self.t.claims.give_back(key)

    def _from_library(self, frame_index: int, action: Action
                      ) -> tuple[tuple[ActionResult, Element | None] | None, int | None]:
        """The action done from the library (its entry, or one that serves it), or why not: (None, the id of the
        exact key's entry written for another version of the primitive set, if any)."""
        primitives = self.t.primitives
        entry = self.t.library.lookup(primitives.name, action.verb, action.signature, self.t.approved_only)
        if entry is not None and not entry.has_plan:  # the model found no plan before: not asked again
            self._count(library_hits=1, no_plan_hits=1)
            reduction = Reduction(action, (), Source.LIBRARY, entry_id=entry.id)
            return (ActionResult(frame_index, reduction, (), entry_validation=entry.validation,
                                 entry_problems=entry.problems), None), None
        body = instantiate(entry.body, placeholders(action)) if entry else None
        plan = self._expand(body) if body is not None else None
        stale = entry.id if entry and not plan else None  # written for another version of the primitive set
        found = self._reusable(action, entry) if not plan and self.t.reuse else None
        reuse = None
        if found is not None:  # learnt for another verb or signature: shown with why it serves
            fit, plan = found
            entry, body, reuse = fit.entry, fit.body, fit.reuse
        if plan:  # a reuse is held to the action's own effect where the table knows it, else to the entry's
            effect = self._effect(action, None if reuse and table_effect(action.verb) is not None else entry.effect)
            if done := self._needless(frame_index, action, effect):
                return (done, None), None
            self._count(library_hits=1, cross_reuses=int(reuse is not None))
            grounded = self._ground(action, plan, "library", effect)
            plan = grounded.plan if grounded else plan
            reduction = Reduction(action, body, Source.LIBRARY, entry_id=entry.id)
            result = ActionResult(frame_index, reduction, plan, entry_validation=entry.validation,
                                  entry_problems=entry.problems, check=grounded, reuse=reuse)
            return (result, plan_element(plan, primitives) if plan else None), None
        return None, stale

    def _from_model(self, frame_index: int, action: Action, stale: int | None
                    ) -> tuple[ActionResult, Element | None]:
        """The action reduced by the model (in the world model where there is one), and learnt."""
        primitives = self.t.primitives
        in_world = (self.t.grounding is not None and hasattr(self.t.model, "complete_lines")
                    and not self.t.settings.comments)  # the line grammar has no comment lines
        effect = self._effect(action)
        if done := self._needless(frame_index, action, effect):
            return done, None
        if in_world:
            checked = self._reduce_in_world(action, effect)
        else:
            checked = reduce_checked(action, primitives, self.verbs, self.t.model, self.t.settings, self._expand,
                                     self.t.validator, self.t.repairs)
        reduction, plan, validation = checked.reduction, checked.plan, checked.validation
        grounded = self._ground(action, plan, "model", effect)
        if grounded is not None:
            self._count(model_lines_applied=int(bool(plan) and grounded.applicable))
            changed = grounded.plan != plan  # lines dropped or completed: the checked plan is what is learnt
            plan = grounded.plan
            if self.t.validator is not None and plan and (in_world or changed):
                validation = self.t.validator.validate(action, plan, self._so_far())  # as it will run, in THOR
            elif self.t.validator is None:
                validation = world_validation(grounded)
            checked = replace(checked, plan=plan, validation=validation)
        self._count_reductions(checked)
        if self.uses_library and not self._awaiting_review(action):
            learnt = reduction if grounded is None else replace(reduction, body=plan)
            reduction = replace(reduction, entry_id=self._learn(action, learnt, plan, validation, stale).entry_id)
        result = ActionResult(frame_index, reduction, plan, validation, checked.failed, check=grounded)
        return result, plan_element(plan, primitives) if plan else None

    def _reusable(self, action: Action, exact: LibraryEntry | None) -> tuple[Fit, tuple[Call, ...]] | None:
        """The best entry of another verb or signature that serves `action` (`library.reuse`), with its plan down
        to primitives; None when none does. The exact key's own entry (stale here) is not tried again."""
        entries = self.t.library.live(self.t.primitives.name, self.t.approved_only)
        for fit in reuses(action, (e for e in entries if exact is None or e.id != exact.id), self.t.approved_only):
            plan = self._expand(fit.body)
            if plan:
                return fit, plan
        return None

    def _reduce_in_world(self, action: Action, effect: tuple) -> Checked:
        """State-aware decoding: every line the model writes can be applied where the recipe has got to."""
        reduction = reduce_in_world(action, self.t.primitives, self.t.model, self.t.settings, self.t.grounding,
                                    self.world_state, effect)
        return Checked(reduction, reduction.body, None)

    def start(self, parsed: ParsedRecipe) -> None:
        """The kitchen before the first step, holding every object the recipe names."""
        grounding = self.t.grounding
        if grounding is not None:
            started = time.perf_counter()
            actions = [a for step in parsed.steps for frame in step.frames for a in actions_of(frame)]
            start = grounding.start(*cast(actions, grounding.world))
            self.world_state = self.world_start = start.state
            self.world_binding, self.scene = dict(start.binding), start.scene
            self._count(world_seconds=time.perf_counter() - started)

    def _so_far(self) -> RecipeSoFar | None:
        """Where the recipe has got to in its THOR kitchen, for the kitchen check; None outside one."""
        return RecipeSoFar(self.scene, self.world_binding, tuple(self.ran)) if self.scene else None

    def _needless(self, frame_index: int, action: Action, effect: tuple) -> ActionResult | None:
        """An action whose effect already holds where it is used (the mug is clean) needs no plan here, and
        teaches the library nothing: no model call, no entry."""
        if not effect or not all_reached(self.world_state, effect):
            return None
        checked = self._ground(action, (), "", effect)
        return ActionResult(frame_index, Reduction(action, (), Source.WORLD), (), check=checked)

    def _effect(self, action: Action, stored: tuple[str, ...] | None = None, write: bool = True) -> tuple:
        """The states `action` must leave (a library entry's `stored` effect, else the table's, else the
        model's if it may `write` one), in the world where the recipe has got to; none without a world."""
        return () if self.intents is None else self.intents.facts(action, self.world_state, stored, write)

    def _ground(self, action: Action, plan: tuple[Call, ...], origin: str, effect: tuple | None = None
                ) -> PlanCheck | None:
        """The plan checked where the recipe has got to, completed to the action's effect; the run moves on."""
        grounding = self.t.grounding
        if grounding is None:
            return None
        effect = self._effect(action) if effect is None else effect
        started = time.perf_counter()
        checked = check_plan(grounding.world, self.world_state, plan, effect, grounding.planner, origin)
        self.world_state = checked.state
        self._count(grounded=1, reached=int(checked.effect_reached), planner_lines=checked.planner_lines,
                    world_seconds=time.perf_counter() - started)
        return checked

    def _learn(self, action: Action, reduction: Reduction, plan: tuple[Call, ...], validation: Validation | None,
               stale: int | None) -> Reduction:
        """Cache a new reduction as a pending entry; without a plan, an empty body that records it."""
        if plan:
            status = validation.status if validation else CheckStatus.UNCHECKED
            body = parametrize(reduction.body, action)
            problems = validation.messages() if validation else ()
        else:
            body, status, problems = "", CheckStatus.FAILED, (NO_PLAN_PROBLEM,)
        effect = None if self.intents is None else [
            template_text(t) for t in self.intents.templates(action, self.world_state)]
        entry = self.t.library.add(self.t.primitives.name, action.verb, action.signature, body, self.t.model.name,
                                   reduction.prompt_hash, replacing=stale, validation=status, problems=problems,
                                   example=placeholders(action), effect=effect)
        self._count(new_entries=1)
        if plan:
            self._refresh()
        return replace(reduction, entry_id=entry.id)

    def _count_reductions(self, checked: Checked) -> None:
        for reduction in checked.model_calls:
            usage = reduction.usage
            self._count(prompt_tokens=usage.prompt_tokens, completion_tokens=usage.completion_tokens,
                        llm_seconds=usage.seconds, dropped_lines=len(reduction.dropped),
                        world_seconds=usage.choice_seconds)
        self._count(llm_calls=1, repair_calls=len(checked.failed))
        if checked.validation is not None and checked.validation.checked:
            passed = checked.validation.passed
            self._count(checked=1, validated=int(passed), repaired=int(checked.repaired))

    def _awaiting_review(self, action: Action) -> bool:
        """In lab mode, an action whose pending entry was skipped: the new plan is used, not cached over it."""
        return self.t.approved_only and self.t.library.lookup(
            self.t.primitives.name, action.verb, action.signature) is not None

    def problems(self, results: list[ActionResult], formula: Formula) -> tuple[str, ...]:
        found = [f"no admissible plan for {r.reduction.action.text()}" for r in results
                 if not r.plan and r.reduction.source != Source.WORLD]
        predicates = {state: 1 for state in self.t.primitives.states} | {ELAPSED: 1}
        predicates |= {value: 1 for r in results for value in r.reduction.action.values}
        predicates |= {c.args[1]: 1 for r in results for c in r.plan if c.is_wait}
        found += [problem.message for problem in check(formula, self.t.primitives, predicates)]
        return tuple(found)

    def _expand(self, body: tuple[Call, ...] | None) -> tuple[Call, ...] | None:
        if body is None:
            return None
        plan = expand(body, self.t.primitives, self._find)
        return plan if plan is not None and all(self._fits(call) for call in plan) else None

    def _fits(self, call: Call) -> bool:
        primitive = self.t.primitives.get(call.name)
        return primitive is not None and len(call.args) == (2 if call.is_wait else primitive.object_arity)

    def _find(self, verb: str, arity: int) -> LibraryVerb | None:
        return next((v for v in self.verbs if v.verb == verb and len(v.signature) == arity), None)

    def _refresh(self) -> None:
        if self.uses_library:
            entries = self.t.library.live(self.t.primitives.name, self.t.approved_only)
            self.verbs, self.skipped_verbs = offered_verbs(LibraryVerb(e.verb, e.signature, e.body) for e in entries)

    def _count(self, **increments) -> None:
        self.stats = replace(self.stats, **{k: getattr(self.stats, k) + v for k, v in increments.items()})


class _TimedCheck:
    """The translator's kitchen check, its time counted in the run's stats (`kitchen_seconds`)."""

    def __init__(self, validator: PlanValidator, count) -> None:
        self.validator, self.count = validator, count

    def validate(self, action: Action, plan: tuple[Call, ...], so_far: RecipeSoFar | None = None) -> Validation:
        started = time.perf_counter()
        try:
            return self.validator.validate(action, plan, so_far)
        finally:
            self.count(kitchen_seconds=time.perf_counter() - started)

    def close(self) -> None:
        self.validator.close()
