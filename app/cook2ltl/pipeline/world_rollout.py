"""A translated recipe rolled out in the world model: step after step in one state, the recipe's formula
progressed after every plan line, and the problems reported by the step they belong to.

`translate` checked each action where the recipe had got to (`ActionResult.check`); this replays the plans
it kept from `Translation.world_start`, line by line with `World.apply`, so what one step leaves (the penne
cooked) is what the next one finds (the pasta drained). Each applied line is one step of the trace, as in a
kitchen rollout (execution/rollout.py): its action atom plus the formula's state predicates that hold after it
(`hot(oven)`). A refused line is no step of the trace: the state stays as it was, and the line is reported.

A negated action ("do not overmix") is not run: the formula asks to avoid it. A generator of progress events
(in the style of `pipeline.translate`); a `threading.Event` stops it between two actions.
"""

from __future__ import annotations

import threading
from collections.abc import Iterator
from dataclasses import dataclass

from cook2ltl.domain.actions import Call, PrimitiveSet
from cook2ltl.errors import UserError
from cook2ltl.formulas.formula import ELAPSED, call_atom, condition_atom
from cook2ltl.ltl.ast import FALSE, Atom, Formula
from cook2ltl.ltl.printer import to_spot, to_unicode
from cook2ltl.ltl.progress import Verdict, progress, verdict
from cook2ltl.pipeline.records import ActionResult, StepResult, Translation
from cook2ltl.world.effects import fact_text
from cook2ltl.world.kitchens import world_of
from cook2ltl.world.logic import Fact, State
from cook2ltl.world.planner import reached
from cook2ltl.world.world import World

NO_WORLD_HINT = "translate it with the world model on (drop --no-ground), with a primitive set that has a [world]."


@dataclass(frozen=True)
class LineRun:
    call: Call
    written_by: str  # model, library, recipe or planner ("" when the translation does not say)
    problem: str  # why the world refused the line; "" when it applied
    added: tuple[Fact, ...]  # facts the line made true
    removed: tuple[Fact, ...]  # facts it made false
    facts: frozenset[Atom]  # the formula's state predicates that hold after it
    remaining: Formula  # the recipe's formula: what the rest of the trace must still do
    verdict: Verdict
    met: frozenset[Atom]  # the formula's atoms made true so far

    @property
    def applied(self) -> bool:
        return not self.problem


@dataclass(frozen=True)
class ActionRun:
    result: ActionResult  # as translated, with its check where the recipe had got to
    lines: tuple[LineRun, ...]
    missing: tuple[Fact, ...]  # of the action's intended effect, what does not hold after its lines
    problems: tuple[str, ...]
    avoided: bool = False  # a negated action: not run

    @property
    def reached(self) -> bool:
        """Its intended effect holds after its lines. Never for an action the world model did not check, nor for
        one with neither a plan nor an effect: nothing shows it was done."""
        check = self.result.check
        return self.avoided or (check is not None and bool(self.result.plan or check.effect) and not self.missing)


@dataclass(frozen=True)
class StepRun:
    result: StepResult
    actions: tuple[ActionRun, ...]
    remaining: Formula  # the step's own formula after its actions
    verdict: Verdict
    problems: tuple[str, ...]

    @property
    def reached(self) -> bool:
        return all(run.reached for run in self.actions)


@dataclass(frozen=True)
class RecipeRollout:
    translation: Translation
    steps: tuple[StepRun, ...]
    remaining: Formula  # the recipe's formula after the last line
    verdict: Verdict
    met: frozenset[Atom]  # the formula's atoms made true by the recipe
    unobservable: tuple[Atom, ...]  # state predicates the world cannot tell: they hold only when waited for
    state: State  # the world after the recipe

    @property
    def success(self) -> bool:
        """Every step left its actions' effects and the recipe's formula holds."""
        return all(step.reached for step in self.steps) and self.verdict.holds


@dataclass(frozen=True)
class Began:
    formula: Formula
    steps: int
    actions: int
    unobservable: tuple[Atom, ...]


@dataclass(frozen=True)
class ActionRolled:
    step: StepResult
    run: ActionRun
    done: int  # actions rolled out so far


@dataclass(frozen=True)
class StepRolled:
    run: StepRun


@dataclass(frozen=True)
class RecipeRolledOut:
    rollout: RecipeRollout


RecipeRolloutEvent = Began | ActionRolled | StepRolled | RecipeRolledOut


def roll_out_recipe(translation: Translation, primitives: PrimitiveSet, world: World | None = None,
                    cancel: threading.Event | None = None) -> Iterator[RecipeRolloutEvent]:
    """Replay `translation` (made with `primitives` and the world model) from the state before its first step.
    Raises UserError for a translation made without the world model."""
    if world is None:
        world = world_of(primitives)
    if world is None or translation.world_start is None:
        raise UserError("A recipe rollout needs the world model, and this translation was made without it.",
                        NO_WORLD_HINT)
    run = _Replay(translation, primitives, world)
    yield Began(translation.formula, len(translation.steps), sum(len(s.actions) for s in translation.steps),
                run.unobservable)
    steps, done = [], 0
    for step in translation.steps:
        runs, step_remaining = [], step.formula
        for result in step.actions:
            if cancel is not None and cancel.is_set():
                return
            action, step_remaining = run.action(step, result, step_remaining)
            runs.append(action)
            done += 1
            yield ActionRolled(step, action, done)
        steps.append(run.step(step, tuple(runs), step_remaining))
        yield StepRolled(steps[-1])
    yield RecipeRolledOut(RecipeRollout(translation, tuple(steps), run.remaining, verdict(run.remaining), run.met,
                                 run.unobservable, run.state))


class _Replay:
    """Where the rollout has got to: the world's state and the recipe formula's remaining obligation."""

    def __init__(self, translation: Translation, primitives: PrimitiveSet, world: World) -> None:
        self.primitives, self.world = primitives, world
        self.state: State = translation.world_start
        self.remaining = translation.formula
        self.met: frozenset[Atom] = frozenset()
        self.atoms = translation.formula.atoms
        self.predicates = frozenset(a for a in self.atoms if primitives.get(a.name) is None)
        self.unobservable = tuple(sorted((a for a in self.predicates if a.name != ELAPSED
                                          and world.predicate(a.name) is None), key=lambda a: a.key))
        self.violated_at: tuple[int, str] | None = None  # the step and line where the formula was first violated

    def action(self, step: StepResult, result: ActionResult, step_formula: Formula) -> tuple[ActionRun, Formula]:
        name = result.reduction.action.text()
        if step.step.frames[result.frame_index].negated:
            return ActionRun(result, (), (), (), avoided=True), step_formula
        check = result.check
        # who wrote each line, where the check says (its plan is the plan kept, unless edited since)
        writers = check.written_by if check is not None and check.plan == result.plan else ("",) * len(result.plan)
        lines = []
        for call, writer in zip(result.plan, writers):
            line, step_formula = self._line(call, writer, step_formula)
            lines.append(line)
            if self.violated_at is None and line.remaining is FALSE:
                self.violated_at = (step.step.index, f"{name}: {call.text()}")
        missing = tuple(f for f in check.effect if not reached(self.state, f)) if check is not None else ()
        problems = [f"{name}: {problem}" for problem in check.problems] if check is not None else []
        problems += [f"{name}: line {i} {line.call.text()}: {line.problem}"
                     for i, line in enumerate(lines, 1) if not line.applied]
        if missing and check.effect_reached:  # translate found it reached; the replay did not
            problems.append(f"{name}: does not reach {', '.join(fact_text(f) for f in missing)} here")
        return ActionRun(result, tuple(lines), missing, tuple(problems)), step_formula

    def step(self, step: StepResult, runs: tuple[ActionRun, ...], remaining: Formula) -> StepRun:
        problems = [*step.problems, *(problem for run in runs for problem in run.problems)]
        step_verdict = verdict(remaining)
        if not step_verdict.holds:
            problems.append(f"the step's formula is {step_verdict.value.replace('_', ' ')}; it still needs "
                            f"{to_unicode(remaining)}")
        if self.violated_at is not None and self.violated_at[0] == step.step.index:
            problems.append(f"the recipe's formula is violated at {self.violated_at[1]}")
        return StepRun(step, runs, remaining, step_verdict, tuple(dict.fromkeys(problems)))

    def _line(self, call: Call, writer: str, step_formula: Formula) -> tuple[LineRun, Formula]:
        before = self.state
        applied = self.world.apply(before, call)
        if not applied.applied:
            return LineRun(call, writer, applied.problem, (), (), frozenset(), self.remaining,
                           verdict(self.remaining), self.met), step_formula
        self.state = applied.state
        facts = self._facts(call)
        action = call_atom(call, self.primitives)
        trace_step = facts | {action} if isinstance(action, Atom) else facts
        self.remaining = progress(self.remaining, trace_step)
        self.met |= trace_step & self.atoms
        added = tuple(sorted(self.state.facts - before.facts))
        removed = tuple(sorted(before.facts - self.state.facts))
        return (LineRun(call, writer, "", added, removed, facts, self.remaining, verdict(self.remaining), self.met),
                progress(step_formula, trace_step))

    def _facts(self, call: Call) -> frozenset[Atom]:
        """The formula's state predicates that hold now; after a wait, also what it waited for where the world
        cannot tell (time passed: a wait stands for any duration, as in a kitchen rollout)."""
        found = set()
        for atom in self.predicates:
            predicate = self.world.predicate(atom.name) if len(atom.args) == 1 else None
            if predicate is not None and (predicate, atom.args[0]) in self.state.facts:
                found.add(atom)
        if call.is_wait and self.world.condition(call) is None:
            found.add(condition_atom(*call.args))
        return frozenset(found)


def recipe_rollout_json(rollout: RecipeRollout) -> dict:
    """Per step its actions, each with translate's `check` and the trace of its lines; the final verdict."""
    return {
        "primitives": rollout.translation.primitives,
        "formula": to_spot(rollout.translation.formula),
        "steps": [_step_json(step) for step in rollout.steps],
        "remaining": to_spot(rollout.remaining),
        "verdict": rollout.verdict.value,
        "unobservable": [atom.text for atom in rollout.unobservable],
        "success": rollout.success,
    }


def _step_json(step: StepRun) -> dict:
    return {
        "index": step.result.step.index,
        "text": step.result.step.sentence.text,
        "formula": to_spot(step.result.formula),
        "actions": [_action_json(run) for run in step.actions],
        "remaining": to_spot(step.remaining),
        "verdict": step.verdict.value,
        "problems": list(step.problems),
    }


def _action_json(run: ActionRun) -> dict:
    """The recipe formula's remaining obligation once, after the action's last line (per line it would repeat the
    whole recipe line after line)."""
    last = next((line for line in reversed(run.lines) if line.applied), None)
    return {
        "action": run.result.reduction.action.text(),
        "plan": [call.text() for call in run.result.plan],
        "avoided": run.avoided,
        "reached": run.reached,
        "check": run.result.check.json() if run.result.check is not None else None,
        "trace": [line_json(line) for line in run.lines],
        "remaining": to_spot(last.remaining) if last else None,
        "verdict": last.verdict.value if last else None,
    }


def line_json(line: LineRun) -> dict:
    return {
        "line": line.call.text(),
        "written_by": line.written_by,
        "applied": line.applied,
        "problem": line.problem,
        "added": [fact_text(f) for f in line.added],
        "removed": [fact_text(f) for f in line.removed],
        "facts": sorted(atom.text for atom in line.facts),
        "verdict": line.verdict.value,
    }
