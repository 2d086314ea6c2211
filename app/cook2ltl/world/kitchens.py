"""Which kitchen a primitive set's plans start in: its kitchen file, or an AI2-THOR kitchen read off THOR's metadata."""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable, Mapping, Sequence

from cook2ltl.domain.actions import PrimitiveSet
from cook2ltl.thor_types import liquids
from cook2ltl.world.check import Grounding, Start
from cook2ltl.world.pddl import load_domain
from cook2ltl.world.planner import FastDownward, Planner
from cook2ltl.world.recipe_kitchen import kitchen_state, read_kitchen
from cook2ltl.world.stand_ins import best_frame, frame_in
from cook2ltl.world.thor_kitchens import scene_objects, scene_start
from cook2ltl.world.world import World


def world_of(primitives: PrimitiveSet) -> World | None:
    spec = primitives.world
    return None if spec is None else World(load_domain(spec.domain), dict(spec.states), spec.liquid_fill)


def grounding(primitives: PrimitiveSet, planner: Planner | None = None, scene: str | None = None,
              complete: bool = True, objects: Callable[[], Sequence[Mapping]] | None = None) -> Grounding | None:
    """The set's world, the planner that completes plans (`complete`) and its start (given the recipe's names,
    those things go into, and the states each must take): the kitchen file with the recipe's names as
    ingredients, or a THOR kitchen: `objects()` (the metadata of a running kitchen, after a
    task's setup), else the scene `scene`, else the scene with most of the names."""
    world = world_of(primitives)
    if world is None:
        return None
    spec = primitives.world
    complete = complete and spec.planner
    if planner is None and complete:
        kit = dict(spec.kit) if spec.kit is not None or spec.kitchen is None else read_kitchen(spec.kitchen).kit
        planner = FastDownward(kit)
    planner = planner if complete else None

    def start(names: Iterable[str], places: Collection[str] = (), asks: Mapping[str, Collection[str]] = {}) -> Start:
        names = tuple(names)
        wanted = tuple(dict.fromkeys((*primitives.objects, *names)))
        if spec.kitchen is not None:
            return Start(kitchen_state(spec.kitchen, wanted), {})
        spare = [n for n in primitives.objects if n not in names]
        if objects is not None:  # a running kitchen: its own objects only
            return Start(*scene_start(objects(), wanted, spare=spare))
        return thor_start(names, places, asks, wanted, spare, scene)

    return Grounding(world, planner, start)


def thor_start(names: tuple[str, ...], places: Collection[str], asks: Mapping[str, Collection[str]],
               wanted: tuple[str, ...], spare: list[str], scene: str | None) -> Start:
    """A THOR kitchen for a recipe, as the kitchen check binds it: the scene where most of the recipe's names find
    an object or a stand-in (an ingredient THOR lacks is a food object, a mixture things go into a bowl, a
    saucepan a pot: `stand_ins`; one that can take the states `asks` names), so the world observes
    what is done to them."""
    own = [n for n in names if n not in liquids()]
    frame = frame_in(scene, own, places, asks) if scene else best_frame(own, places, asks)
    state, binding = scene_start(scene_objects(frame.scene), wanted, frame.bound, spare)
    return Start(state, binding, frame.scene)
