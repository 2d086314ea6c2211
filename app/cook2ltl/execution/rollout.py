"""A formula executed in a kitchen, with what is satisfied and what remains after every action.

The paper's "minimal parser that receives an LTL formula and converts it to a
series of actions", done with LTLf progression instead of pattern matching, so
it reads any formula the translator builds (sequences ◇(a ∧ ◇(b ∧ …)), ∧, ∨, ¬,
𝒰) and hand-written ones alike:

* the next action is an action atom of the remaining obligation that makes
  progress on it (progressing by it gives neither ⊥ nor the same obligation);
  several (the branches of an ∨, the parts of an "all of") are tried in the
  order they appear, the next one when THOR refuses the first;
* an action that would violate the obligation (a ¬a, an avoided step) is never
  chosen;
* when nothing makes progress, the agent keeps doing what the left side of an
  Until asks: `wait 𝒰 hot(potato)` waits (THOR's Pass) until the kitchen
  reports hot(potato), at most `RolloutLimits.max_waits` times in a row.

Each step of the trace is the action done plus the formula's state predicates
that hold after it (see `facts`), so progression sees both. A refused action
is not a step: it happened in no trace. When every candidate is refused the
rollout ends there, with THOR's errorMessage; it does not repair the plan.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass
from enum import StrEnum

from cook2ltl.domain.actions import WAIT
from cook2ltl.errors import UserError
from cook2ltl.execution.executor import Attempt, Kitchen, execute, thor_primitives
from cook2ltl.ltl.ast import FALSE, Atom, Formula, Until, WeakUntil, postorder
from cook2ltl.ltl.printer import to_spot, to_unicode
from cook2ltl.ltl.progress import Verdict, progress, verdict
from cook2ltl.thor_types import liquids
from cook2ltl.world.thor_facts import observable, true_facts
from cook2ltl.world.thor_names import Binding, UnknownObject, check_names


class Stop(StrEnum):
    SATISFIED = "satisfied"  # the trace satisfies the formula if it ends here
    VIOLATED = "violated"  # no continuation can satisfy it any more
    FAILED = "failed"  # THOR refused every action that would make progress
    WAITED = "waited"  # waited max_waits steps for a condition the kitchen never reported
    STUCK = "stuck"  # no action of the formula makes progress
    STEP_LIMIT = "step limit"
    CANCELLED = "cancelled"


@dataclass(frozen=True)
class RolloutLimits:
    max_waits: int = 3
    max_steps: int = 100


@dataclass(frozen=True)
class TraceStep:
    index: int  # 1 for the first action
    attempt: Attempt  # the action done, with its THOR calls
    facts: frozenset[Atom]  # the formula's state predicates that hold after it
    remaining: Formula  # what the rest of the trace must still do
    verdict: Verdict
    met: frozenset[Atom]  # the formula's atoms made true so far

    @property
    def atoms(self) -> frozenset[Atom]:
        """The step as progression saw it."""
        return self.facts | {self.attempt.atom}


@dataclass(frozen=True)
class Rollout:
    formula: Formula
    scene: str
    steps: tuple[TraceStep, ...]
    failures: tuple[Attempt, ...]  # refused attempts; with stop FAILED the last ones ended the rollout
    stop: Stop
    verdict: Verdict
    binding: Binding
    unobservable: tuple[Atom, ...]  # predicates the kitchen cannot report: never true
    seconds: float


@dataclass(frozen=True)
class RolloutStarted:
    formula: Formula
    scene: str
    unobservable: tuple[Atom, ...]


@dataclass(frozen=True)
class ActionRefused:
    attempt: Attempt


@dataclass(frozen=True)
class Stepped:
    step: TraceStep


@dataclass(frozen=True)
class RolloutFinished:
    rollout: Rollout


RolloutEvent = RolloutStarted | ActionRefused | Stepped | RolloutFinished


def rollout(kitchen: Kitchen, formula: Formula, preferred: frozenset[str] = frozenset(),
            limits: RolloutLimits = RolloutLimits(), cancel: threading.Event | None = None,
            binding: Binding = Binding()) -> Iterator[RolloutEvent]:
    """Execute `formula` in the kitchen's current scene, yielding after every action.

    `preferred` are objectIds to choose when a name fits several objects (the
    ones a task's goal names). Raises UserError for a formula this kitchen
    cannot execute at all: an unknown primitive arity, object or liquid.
    """
    started = time.perf_counter()
    metadata = kitchen.last_event.metadata
    scene = metadata["sceneName"].removesuffix("_physics")
    actions, predicates = check_formula(formula, metadata["objects"], scene, frozenset(binding.objects))
    unobservable = tuple(sorted((p for p in predicates if not observable(p)), key=lambda a: a.key))
    yield RolloutStarted(formula, scene, unobservable)
    remaining, waits = formula, 0
    steps: list[TraceStep] = []
    failures: list[Attempt] = []
    met: frozenset[Atom] = frozenset()
    facts = true_facts(predicates, metadata["objects"], binding, waited=False)
    while True:
        stop = _stop(remaining, len(steps), limits, cancel)
        if stop is not None:
            break
        useful, hold = choose(remaining, facts, actions)
        if not useful and hold is not None and waits >= limits.max_waits:
            stop = Stop.WAITED
            break
        done = None
        for atom in useful or ([hold] if hold is not None else []):
            attempt, binding = execute(kitchen, atom, binding, preferred)
            if attempt.success:
                done = attempt
                break
            failures.append(attempt)
            yield ActionRefused(attempt)
        if done is None:
            stop = Stop.FAILED if useful or hold is not None else Stop.STUCK
            break
        waits = 0 if useful else waits + 1
        objects = kitchen.last_event.metadata["objects"]
        facts = true_facts(predicates, objects, binding, waited=done.atom.name == WAIT)
        step = facts | {done.atom}
        remaining = progress(remaining, step)
        met = met | (step & formula.atoms)
        steps.append(TraceStep(len(steps) + 1, done, facts, remaining, verdict(remaining), met))
        yield Stepped(steps[-1])
    yield RolloutFinished(Rollout(formula, scene, tuple(steps), tuple(failures), stop, verdict(remaining), binding,
                           unobservable, time.perf_counter() - started))


def choose(remaining: Formula, facts: frozenset[Atom], actions: tuple[Atom, ...]) -> tuple[list[Atom], Atom | None]:
    """(actions that make progress, in formula order; an action the formula holds until a condition, or None)."""
    idle = progress(remaining, facts)
    held = held_atoms(remaining)
    useful, hold = [], None
    for atom in actions:
        if atom not in remaining.atoms:
            continue
        after = progress(remaining, facts | {atom})
        if after is FALSE:
            continue
        if after is not remaining and after is not idle:
            useful.append(atom)
        elif atom in held and hold is None:
            hold = atom
    return useful, hold


def held_atoms(formula: Formula) -> frozenset[Atom]:
    """The atoms on the left of an Until: what `wait(cond)` and "stir until thick" keep doing."""
    return frozenset().union(*(n.left.atoms for n in postorder(formula) if isinstance(n, (Until, WeakUntil))))


def check_formula(formula: Formula, objects, scene: str, bound: frozenset[str] = frozenset()
                  ) -> tuple[tuple[Atom, ...], frozenset[Atom]]:
    """(the action atoms in the order they appear, the predicate atoms); UserError for what cannot run.
    `bound` names stand for objects already chosen (the world model's `drawer_2`)."""
    primitives = thor_primitives()
    actions = tuple(a for a in in_order(formula) if primitives.get(a.name) is not None)
    for atom in actions:
        want = primitives.get(atom.name).object_arity  # wait takes none: its condition is the Until's goal
        if len(atom.args) != want:
            hint = ("wait is the left side of an Until: wait U hot(potato)." if atom.name == WAIT
                    else "see assets/primitives/ai2thor.toml for the primitives and their parameters.")
            raise UserError(f"{atom.text}: {atom.name} takes {want} argument{'s' if want != 1 else ''}.", hint)
        if atom.name == "fill" and atom.args[1] not in liquids():
            raise UnknownObject(f"No liquid {atom.args[1]!r} in {scene}.",
                                f"THOR fills with {', '.join(sorted(liquids()))}.")
    names = [arg for a in actions for arg in (a.args[:1] if a.name == "fill" else a.args)]
    check_names([name for name in names if name not in bound], objects, scene)
    return actions, formula.atoms - frozenset(actions)


def in_order(formula: Formula) -> list[Atom]:
    """The formula's atoms in the order they are written (canonical order for ∧ and ∨), each once."""
    seen: dict[Atom, None] = {}
    expanded: set[Formula] = set()  # a shared subformula's atoms are all seen at its first visit
    stack = [formula]
    while stack:  # a loop: long recipes nest deeper than Python's recursion limit
        node = stack.pop()
        if isinstance(node, Atom):
            seen.setdefault(node)
        elif node not in expanded:
            expanded.add(node)
            stack.extend(reversed(node.children))
    return list(seen)


def _stop(remaining: Formula, done: int, limits: RolloutLimits, cancel: threading.Event | None) -> Stop | None:
    if remaining is FALSE:
        return Stop.VIOLATED
    if verdict(remaining).holds:
        return Stop.SATISFIED
    if cancel is not None and cancel.is_set():
        return Stop.CANCELLED
    if done >= limits.max_steps:
        return Stop.STEP_LIMIT
    return None


def rollout_json(result: Rollout) -> dict:
    return {
        "scene": result.scene,
        "formula": to_spot(result.formula),
        "formula_unicode": to_unicode(result.formula),
        "trace": [step_json(step) for step in result.steps],
        "refused": [attempt_json(a) for a in result.failures],
        "stop": result.stop.value,
        "verdict": result.verdict.value,
        "bindings": dict(result.binding.objects),
        "unobservable": [a.text for a in result.unobservable],
    }


def step_json(step: TraceStep) -> dict:
    return {
        "index": step.index,
        **attempt_json(step.attempt),
        "facts": sorted(a.text for a in step.facts),
        "met": sorted(a.text for a in step.met),
        "remaining": to_spot(step.remaining),
        "remaining_unicode": to_unicode(step.remaining),
        "verdict": step.verdict.value,
    }


def attempt_json(attempt: Attempt) -> dict:
    return {
        "action": attempt.atom.text,
        "success": attempt.success,
        "error": attempt.error,
        "thor": [{**call.action, "success": call.success, "error": call.error} for call in attempt.calls],
    }
