"""A plan checked against its intended effect in the world model, and completed by the planner where it falls short.

The lines are applied in order from the state the action starts in; a line that cannot be applied there is
dropped and reported (the state stays as it was). If the intended effect does not hold at the end, the
planner writes the rest from the state reached (LLM+P, Liu et al. 2023); with no lines at all it writes the
whole plan, and where the lines led to a state the effect cannot be reached from, its plan from the start
replaces them. Lines the effect does not need are then dropped (`pruned`). Every line keeps who wrote it.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import NamedTuple, Protocol

from cook2ltl.domain.actions import Call
from cook2ltl.world.effects import fact_text
from cook2ltl.world.logic import Fact, State
from cook2ltl.world.planner import Planner, all_reached, reached
from cook2ltl.world.world import KEPT, World

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
    scene: str = ""  # the THOR scene the binding is in; "" for a kitchen file or a running kitchen


class Starter(Protocol):
    """How a run starts in a world: its state and binding, given the recipe's names, the places things go into
    and the states each name is asked to take (`effects.cast`)."""

    def __call__(self, names: Iterable[str], places: Collection[str] = (),
                 asks: Mapping[str, Collection[str]] = {}) -> Start: ...


@dataclass(frozen=True)
class Grounding:
    """What checking needs: the world, the planner (None: check only, never complete) and how a run starts."""

    world: World
    planner: Planner | None
    start: Starter


def check_plan(world: World, state: State, plan: Sequence[Call], effect: Sequence[Fact], planner: Planner | None,
               origin: str = "model") -> PlanCheck:
    start = state
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
        if rest is None and kept:  # the lines led where the effect cannot be reached: the planner's way instead
            rest = planner.plan(world, start, tuple(effect))
            if rest is not None:
                problems.append(f"the effect cannot be reached after {kept[-1].text()}: the planner's plan instead")
                kept, written_by, state = [], [], start
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
    done = all_reached(state, effect)
    if done and effect:
        kept, written_by, state = pruned(world, start, list(zip(kept, written_by)), effect)
    return PlanCheck(applicable, tuple(effect), done, tuple(kept), tuple(written_by), tuple(problems), state)


def pruned(world: World, start: State, lines: list[tuple[Call, str]], effect: Sequence[Fact]
           ) -> tuple[list[Call], list[str], State]:
    """Greedy action elimination (Nakhost and Müller 2010): a line is dropped, with the later lines that no
    longer apply without it, when the rest still reaches the effect and leaves the kitchen no further from how
    the action found it. A model's wandering (the tomato microwaved before it is chopped) goes; lines that
    tidy up (closing the fridge, switching the oven off) stay."""
    lines, states = _replay(world, start, lines)  # states[k]: after the first k lines
    index = 0
    while index < len(lines):
        rest, after = _replay(world, states[index], lines[index + 1:])
        if all_reached(after[-1], effect) and _changes(after[-1], start) <= _changes(states[-1], start):
            lines, states = lines[:index] + rest, states[:index + 1] + after[1:]
        else:
            index += 1
    return [call for call, _ in lines], [source for _, source in lines], states[-1]


def _changes(state: State, start: State) -> int:
    """How many facts of the kitchen differ from `start`, leaving out what the domains only keep as
    bookkeeping (what is shut away or carried follows from the rest)."""
    return sum(1 for fact in state.facts ^ start.facts if fact[0] not in KEPT)


def _replay(world: World, state: State, lines: list[tuple[Call, str]]
            ) -> tuple[list[tuple[Call, str]], list[State]]:
    """The lines that apply in order from `state` (the others skipped), and the states from `state` on."""
    kept, states = [], [state]
    for call, source in lines:
        step = world.apply(states[-1], call)
        if step.applied:
            kept.append((call, source))
            states.append(step.state)
    return kept, states
