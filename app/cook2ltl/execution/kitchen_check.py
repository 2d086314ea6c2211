"""A new reduction checked before it is cached: its plan run line by line in the embedded THOR kitchen.

The paper's failure mode is a wrong first plan cached and then reused everywhere. `KitchenValidator` runs
the plan (library verbs expanded down to primitives) through ai2thor's own Controller on the embedded
kitchen, in the kitchen that has most of its objects (see `world.stand_ins` for the stand-ins), and
reports every line THOR refuses with THOR's reason: a put before any pick up, a put into a closed fridge,
a slice without a knife in hand, an object the kitchen does not have. A refused line changes nothing and
the run goes on, so a plan gets every problem at once. Translating in the world model, a plan runs where the
recipe has got to (`RecipeSoFar`): in the recipe's kitchen, after the lines of its earlier actions.

Goal states are checked where the plan or action states one the kitchen can observe: `wait(potato ==
hot)` waits (THOR's Pass) up to `MAX_WAITS` times for the potato to be hot, and an action whose time or
temperature is such a state (`chill(apple, until_cold)`), or whose verb implies one (chop: sliced,
microwave: hot, refrigerate: cold; `plan_run.VERB_GOALS`), must leave its first object in it, so
`pick_up(tomato)` alone does not pass for chopping it. States the kitchen cannot see (boiled, golden,
thick) and timers are not checked.

Both shipped primitive sets run: the ai2thor set as THOR actions, and any other set through its file's
`[thor]` table (recipe.toml: cut → slice, remove → pick_up, stir / shake / taste / turn touch an object
that must be within reach, pour fills with a liquid or needs the poured thing in hand; put, open, wait…
are the AI2-THOR set's own). A set with other primitives cannot be checked (`unsupported`).
"""

from __future__ import annotations

import time

from cook2ltl.domain.actions import Action, Call, PrimitiveSet
from cook2ltl.errors import UserError
from cook2ltl.execution.launcher import start_embedded
from cook2ltl.execution.plan_run import PlanRun, meanings
from cook2ltl.reduce.validation import LineProblem, RecipeSoFar, Validation
from cook2ltl.thor_types import liquids
from cook2ltl.world.stand_ins import Casting, build_frame


def unsupported(primitives: PrimitiveSet) -> tuple[str, ...]:
    """The primitives of a set the kitchen cannot run (empty for the shipped sets)."""
    runnable = meanings(primitives)
    return tuple(p.name for p in primitives.primitives if p.name not in runnable)


class KitchenValidator:
    """Runs plans in one embedded kitchen, started at the first plan and stopped by `close`."""

    def __init__(self, primitives: PrimitiveSet) -> None:
        self._meaning = meanings(primitives)
        missing = [p.name for p in primitives.primitives if p.name not in self._meaning]
        if missing:
            raise UserError(f"The kitchen cannot check plans of the primitive set {primitives.name!r}: it has no "
                            f"action for {', '.join(missing)}.", "translate with --no-validate.")
        self.primitives = primitives
        self._controller = None

    def validate(self, action: Action, plan: tuple[Call, ...], so_far: RecipeSoFar | None = None) -> Validation:
        """The plan run alone, in the kitchen that fits it best with its shut-away things set out, or, given
        `so_far`, after the recipe's earlier lines in the recipe's own kitchen."""
        started = time.perf_counter()
        frame = build_frame(plan, liquids()) if so_far is None else Casting(so_far.scene, so_far.binding)
        if frame.missing:
            problem = LineProblem(0, action.text(), f"not checked: the THOR kitchen has nothing that can stand for "
                                                    f"{', '.join(frame.missing)}")
            return Validation(False, (problem,), frame.scene, time.perf_counter() - started, checked=False)
        kitchen = self._kitchen()
        kitchen.reset(frame.scene)
        problems = PlanRun(kitchen, frame, self._meaning).run(action, plan, None if so_far is None else so_far.before)
        return Validation(not problems, problems, frame.scene, time.perf_counter() - started)

    def close(self) -> None:
        if self._controller is not None:
            controller, self._controller = self._controller, None
            controller.stop()

    def _kitchen(self):
        if self._controller is None:
            self._controller = start_embedded("FloorPlan1")
        return self._controller

    def __enter__(self) -> KitchenValidator:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
