"""A new reduction checked before it is cached: its plan run line by line in the embedded THOR kitchen.

The paper's failure mode is a wrong first plan cached and then reused everywhere. `KitchenValidator` runs
the plan (library verbs expanded down to primitives) through ai2thor's own Controller on the embedded
kitchen, in the kitchen that has most of its objects (see `validation_scene` for the stand-ins), and
reports every line THOR refuses with THOR's reason: a put before any pick up, a put into a closed fridge,
a slice without a knife in hand, an object the kitchen does not have. A refused line changes nothing and
the run goes on, so a plan gets every problem at once. Translating in the world model, a plan runs where the
recipe has got to (`RecipeSoFar`): in the recipe's kitchen, after the lines of its earlier actions.

Goal states are checked where the plan or action states one the kitchen can observe: `wait(potato ==
hot)` waits (THOR's Pass) up to `MAX_WAITS` times for the potato to be hot, and an action whose time or
temperature is such a state (`chill(apple, until_cold)`), or whose verb implies one (chop: sliced,
microwave: hot, refrigerate: cold; `validation_run.VERB_GOALS`), must leave its first object in it, so
`pick_up(tomato)` alone does not pass for chopping it. States the kitchen cannot see (boiled, golden,
thick) and timers are not checked.

Both shipped primitive sets run: the ai2thor set as THOR actions, and the recipe set through `MEANING`
(cut → SliceObject, remove → PickupObject, stir / shake / taste / turn touch an object that must be
within reach, pour fills with a liquid or needs the poured thing in hand). A set with other primitives
cannot be checked (`unsupported`).
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Protocol

from cook2ltl.errors import UserError
from cook2ltl.reduce.model import Action, Call, PrimitiveSet

MAX_WAITS = 3
# Primitive name → what it does in the kitchen; names the ai2thor executor runs map to themselves.
EXECUTED = ("pick_up", "put", "drop", "open", "close", "break", "cook", "slice", "turn_on", "turn_off", "use",
            "fill", "empty")
TOUCH, POUR, WAIT = "touch", "pour", "wait"
MEANING = {**{name: name for name in EXECUTED}, "cut": "slice", "remove": "pick_up", "pour": POUR,
           "stir": TOUCH, "shake": TOUCH, "taste": TOUCH, "turn": TOUCH, "wait": WAIT}


@dataclass(frozen=True)
class LineProblem:
    line: int  # 1-based in the plan; 0 for the whole plan
    call: str
    message: str

    def text(self) -> str:
        return f"line {self.line} {self.call}: {self.message}" if self.line else f"{self.call}: {self.message}"


@dataclass(frozen=True)
class Validation:
    passed: bool
    problems: tuple[LineProblem, ...]
    scene: str
    seconds: float
    checked: bool = True  # False when the kitchen has nothing that can stand for an object of the plan

    def messages(self) -> tuple[str, ...]:
        return tuple(problem.text() for problem in self.problems)

    @property
    def status(self) -> str:
        """The library's `validation` column: passed, failed or unchecked."""
        return "unchecked" if not self.checked else "passed" if self.passed else "failed"


@dataclass(frozen=True)
class RecipeSoFar:
    """Where a recipe has got to in a THOR kitchen: the scene, the object each name stands for, and the lines
    its earlier actions ran. A plan checked here runs after them, as it will in the recipe."""

    scene: str
    binding: Mapping[str, str]
    before: tuple[Call, ...] = ()


class PlanValidator(Protocol):
    def validate(self, action: Action, plan: tuple[Call, ...], so_far: RecipeSoFar | None = None) -> Validation: ...

    def close(self) -> None: ...


def unsupported(primitives: PrimitiveSet) -> tuple[str, ...]:
    """The primitives of a set the kitchen cannot run (empty for the shipped sets)."""
    return tuple(p.name for p in primitives.primitives if p.name not in MEANING)


class KitchenValidator:
    """Runs plans in one embedded kitchen, started at the first plan and stopped by `close`."""

    def __init__(self, primitives: PrimitiveSet) -> None:
        missing = unsupported(primitives)
        if missing:
            raise UserError(f"The kitchen cannot check plans of the primitive set {primitives.name!r}: it has no "
                            f"action for {', '.join(missing)}.", "translate with --no-validate.")
        self.primitives = primitives
        self._controller = None

    def validate(self, action: Action, plan: tuple[Call, ...], so_far: RecipeSoFar | None = None) -> Validation:
        """The plan run alone, in the kitchen that fits it best with its shut-away things set out, or, given
        `so_far`, after the recipe's earlier lines in the recipe's own kitchen."""
        from cook2ltl.kitchen.executor import liquids
        from cook2ltl.reduce.validation_scene import Frame, build_frame

        started = time.perf_counter()
        frame = build_frame(plan, liquids()) if so_far is None else Frame(so_far.scene, so_far.binding)
        if frame.missing:
            problem = LineProblem(0, action.text(), f"not checked: the THOR kitchen has nothing that can stand for "
                                                    f"{', '.join(frame.missing)}")
            return Validation(False, (problem,), frame.scene, time.perf_counter() - started, checked=False)
        kitchen = self._kitchen()
        kitchen.reset(frame.scene)
        from cook2ltl.reduce.validation_run import PlanRun

        problems = PlanRun(kitchen, frame).run(action, plan, None if so_far is None else so_far.before)
        return Validation(not problems, problems, frame.scene, time.perf_counter() - started)

    def close(self) -> None:
        if self._controller is not None:
            controller, self._controller = self._controller, None
            controller.stop()

    def _kitchen(self):
        if self._controller is None:
            from cook2ltl.kitchen.launcher import start_embedded

            self._controller = start_embedded("FloorPlan1")
        return self._controller

    def __enter__(self) -> KitchenValidator:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
