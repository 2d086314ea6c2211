"""One trial: a formula rolled out in a freshly reset kitchen, and for a task, its goal checked after.

Shared by `cook2ltl rollout` and bench/rollout_bench.py. The events are the
rollout's own, then `TrialDone`; a display or a UI worker forwards them.
"""

from __future__ import annotations

import threading
from collections.abc import Iterator
from dataclasses import dataclass

from cook2ltl.assembly.planning import Plan, plan_json
from cook2ltl.errors import UserError
from cook2ltl.execution.executor import Kitchen
from cook2ltl.execution.rollout import (
    Rollout, RolloutEvent, RolloutFinished, RolloutLimits, Stop, rollout, rollout_json,
)
from cook2ltl.execution.tasks import GoalCheck, Task, check_goal, goal_json, preferred_objects, set_up, task_json
from cook2ltl.formulas.formula import plan_element
from cook2ltl.ltl.ast import Formula
from cook2ltl.ltl.patterns import sequenced_visit
from cook2ltl.reduce.body import read_body
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.world.thor_names import Binding


@dataclass(frozen=True)
class Trial:
    task: Task | None
    plan: Plan | None  # None for a formula given by hand or a task's reference plan
    rollout: Rollout
    goal: GoalCheck | None  # None without a task

    @property
    def success(self) -> bool:
        """The paper's success: the task's goal conditions hold; without a task, the formula does."""
        return self.goal.met if self.goal is not None else self.rollout.verdict.holds

    @property
    def seconds(self) -> float:
        return self.rollout.seconds + (self.plan.seconds if self.plan else 0.0)


@dataclass(frozen=True)
class TrialDone:
    trial: Trial


def run_trial(kitchen: Kitchen, formula: Formula, scene: str, task: Task | None = None, plan: Plan | None = None,
              limits: RolloutLimits = RolloutLimits(), cancel: threading.Event | None = None
              ) -> Iterator[RolloutEvent | TrialDone]:
    """Reset the kitchen to `scene`, set the task up, roll the formula out, check the goal."""
    kitchen.reset(scene)
    if task is not None:
        set_up(kitchen, task)
    preferred = preferred_objects(task, kitchen.last_event.metadata["objects"]) if task else frozenset()
    result = None
    binding = Binding(objects=plan.binding) if plan is not None else Binding()
    for event in rollout(kitchen, formula, preferred, limits, cancel, binding):
        if isinstance(event, RolloutFinished):
            result = event.rollout
        yield event
    goal = check_goal(task, kitchen.last_event.metadata["objects"]) if task else None
    yield TrialDone(Trial(task, plan, result, goal))


def explain(result: Rollout) -> str:
    """Why the rollout ended, in a sentence."""
    if result.stop == Stop.FAILED:
        return result.failures[-1].error
    if result.stop == Stop.STUCK and result.unobservable:
        return f"no action makes progress; the kitchen cannot report {', '.join(a.text for a in result.unobservable)}"
    return {
        Stop.SATISFIED: "the trace satisfies the formula",
        Stop.VIOLATED: "the trace violates the formula",
        Stop.WAITED: "waited, but the condition never held",
        Stop.STUCK: "no action of the formula makes progress",
        Stop.STEP_LIMIT: "too many steps",
        Stop.CANCELLED: "cancelled",
    }[result.stop]


def trial_json(trial: Trial, backend: str) -> dict:
    return {
        "task": task_json(trial.task) if trial.task else None,
        "backend": backend,
        "plan": plan_json(trial.plan) if trial.plan else None,
        **rollout_json(trial.rollout),
        "reason": explain(trial.rollout),
        "goal": goal_json(trial.goal) if trial.goal else None,
        "success": trial.success,
        "seconds": {"plan": round(trial.plan.seconds, 3) if trial.plan else 0.0,
                    "rollout": round(trial.rollout.seconds, 4), "total": round(trial.seconds, 3)},
    }


def reference_formula(task: Task) -> Formula:
    """The task's reference plan as the translator would write it: a sequenced visit of its lines."""
    calls, unread = read_body("\n".join(task.reference))
    if unread or not calls:
        raise UserError(f"Task {task.id}: its reference plan has lines that are not calls: {', '.join(unread)}.")
    return sequenced_visit(plan_element(calls, load_primitives("ai2thor")))
