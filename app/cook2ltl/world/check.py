"""A plan checked against its intended effect in the world model, and completed by the planner where it falls short.

The lines are applied in order from the state the action starts in; a line that cannot be applied there is
dropped and reported (the state stays as it was). If the intended effect does not hold at the end, the
planner writes the rest from the state reached (LLM+P, Liu et al. 2023); with no lines at all it writes the
whole plan. Every line keeps who wrote it.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import NamedTuple

from cook2ltl.reduce.model import Call
from cook2ltl.world.effects import fact_text
from cook2ltl.world.logic import Fact, State
from cook2ltl.world.planner import Planner, reached
from cook2ltl.world.world import World

PLANNER = "planner"


@dataclass(frozen=True)
class PlanCheck:
    applicable: bool  # every line as written applied, in order
    effect: tuple[Fact, ...]  # the states the action must leave
    effect_reached: bool
    plan: tuple[Call, ...]  # the lines kept, then the planner's
    written_by: tuple[str, ...]  # per line of `plan`: who wrote it (model, library, recipe, planner)
    problems: tuple[str, ...]
    state: State  # after `plan`

    @property
    def planner_lines(self) -> int:
        return sum(1 for source in self.written_by if source == PLANNER)

    @property
    def passed(self) -> bool:
        return self.applicable and self.effect_reached

    def json(self) -> dict:
        return {"applicable": self.applicable, "effect": [fact_text(f) for f in self.effect],
                "effect_reached": self.effect_reached, "planner_lines": self.planner_lines,
                "problems": list(self.problems), "written_by": list(self.written_by)}


class Start(NamedTuple):
    """The kitchen before the first step, and the object each name stands for in a THOR kitchen (the rollout
    acts on the objects the plans were made for)."""

    state: State
    binding: Mapping[str, str]


@dataclass(frozen=True)
class Grounding:
    """What checking needs: the world, the planner (None: check only, never complete) and how a run starts."""

    world: World
    planner: Planner | None
    start: Callable[[Iterable[str]], Start]  # given the recipe's names


def check_plan(world: World, state: State, plan: Sequence[Call], effect: Sequence[Fact], planner: Planner | None,
               origin: str = "model") -> PlanCheck:
    kept: list[Call] = []
    problems: list[str] = []
    for line, call in enumerate(plan, 1):
        step = world.apply(state, call)
        if step.applied:
            kept.append(call)
            state = step.state
        else:
            problems.append(f"line {line} {call.text()}: {step.problem}")
    applicable = not problems
    written_by = [origin] * len(kept)
    missing = [fact for fact in effect if not reached(state, fact)]
    if missing and planner is not None:
        rest = planner.plan(world, state, tuple(effect))
        if rest is None:
            problems.append(f"no plan reaches {', '.join(fact_text(f) for f in missing)} from here")
        else:
            for call in rest:
                step = world.apply(state, call)
                if not step.applied:  # the planner saw a narrower kitchen; never keep a line that cannot run
                    problems.append(f"the planner's {call.text()} cannot be applied: {step.problem}")
                    break
                state = step.state
                kept.append(call)
                written_by.append(PLANNER)
    elif missing:
        problems.append(f"the plan does not reach {', '.join(fact_text(f) for f in missing)}")
    done = all(reached(state, fact) for fact in effect)
    return PlanCheck(applicable, tuple(effect), done, tuple(kept), tuple(written_by), tuple(problems), state)
