"""A translation as PDDL for downstream planners: the domain, the problem (the kitchen before the recipe, the
intended effects that hold at its end as the goal) and the plan, each line a domain action.

A wait is written as the processes that act while it lasts (processes only add and remove states no process
tests, so taking them one after another is the same as at once).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from cook2ltl.domain.actions import Call
from cook2ltl.world.logic import Fact, State, bindings, holds
from cook2ltl.world.planner import build_problem, reached
from cook2ltl.world.world import PROCESS, World


def export_pddl(world: World, start: State, plan: Sequence[Call], effects: Sequence[Fact], folder: Path) -> list[Path]:
    from unified_planning.io import PDDLWriter  # heavy: unified-planning (~1 s) loads only for --pddl

    folder.mkdir(parents=True, exist_ok=True)
    lines, state = [], start
    for call in plan:
        lines.extend(_actions(world, state, call))
        state = world.apply(state, call).state
    goal = tuple(dict.fromkeys(fact for fact in effects if reached(state, fact)))
    writer = PDDLWriter(build_problem(world.domain.path, start, goal))
    paths = [folder / "domain.pddl", folder / "problem.pddl", folder / "plan.pddl"]
    writer.write_domain(str(paths[0]))
    writer.write_problem(str(paths[1]))
    paths[2].write_text("".join(line + "\n" for line in lines), encoding="utf-8")
    return paths


def _actions(world: World, state: State, call: Call) -> list[str]:
    if not call.is_wait:
        return [f"({' '.join((call.name, *call.args))})"]
    fired = [f"; {call.text()}"]
    for schema in world.domain.schemas.values():
        if schema.name.startswith(PROCESS):
            for env in bindings(schema.parameters, schema.precondition, state, {}):
                if holds(schema.precondition, state, env):
                    fired.append(f"({' '.join((schema.name, *(env[p] for p in schema.parameters)))})")
    return fired
