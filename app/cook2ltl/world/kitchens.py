"""Which kitchen a primitive set's plans start in: its kitchen file, or an AI2-THOR kitchen read off THOR's metadata."""

from __future__ import annotations

from collections.abc import Iterable

from cook2ltl.reduce.model import PrimitiveSet
from cook2ltl.world.check import Grounding
from cook2ltl.world.logic import State
from cook2ltl.world.planner import FastDownward, Planner
from cook2ltl.world.pddl import load_domain
from cook2ltl.world.world import World


def world_of(primitives: PrimitiveSet) -> World | None:
    spec = primitives.world
    return None if spec is None else World(load_domain(spec.domain), dict(spec.states))


def grounding(primitives: PrimitiveSet, planner: Planner | None = None, scene: str | None = None,
              complete: bool = True) -> Grounding | None:
    """The set's world, the planner that completes plans (`complete`) and its start: the kitchen file with the
    recipe's names as ingredients, or the THOR kitchen `scene` (default: the one with most of the names)."""
    world = world_of(primitives)
    if world is None:
        return None
    spec = primitives.world
    if planner is None and complete:
        from cook2ltl.world.recipe_kitchen import read_kitchen

        planner = FastDownward(read_kitchen(spec.kitchen).kit if spec.kitchen is not None else None)
    planner = planner if complete else None

    def start(names: Iterable[str]) -> State:
        wanted = tuple(dict.fromkeys((*primitives.objects, *names)))
        if spec.kitchen is not None:
            from cook2ltl.world.recipe_kitchen import kitchen_state

            return kitchen_state(spec.kitchen, wanted)
        from cook2ltl.world.thor_kitchens import scene_state

        return scene_state(scene, wanted)

    return Grounding(world, planner, start)
