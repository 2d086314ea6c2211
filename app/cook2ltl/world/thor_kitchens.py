"""The AI2-THOR kitchens as world-model states: a scene's objects as THOR reports them, the names of a recipe bound
to them (`thor.thor_state`).

`scene_names` and `scene_objects` are the one place the world model and the stand-ins learn what the 30 kitchens
hold: THOR's metadata of each at its start (read from the scenes the embedded kitchen ships, as a THOR build
reports them after a reset); nothing else here reads the simulator's state."""

from __future__ import annotations

from collections.abc import Collection, Iterable, Mapping, Sequence
from functools import cache

from cook2ltl.simulator import scenes
from cook2ltl.simulator.metadata import objects_metadata
from cook2ltl.thor_types import load_type_rules
from cook2ltl.world.logic import State
from cook2ltl.world.thor import thor_state


def scene_start(objects: Sequence[Mapping], names: Iterable[str], bound: Mapping[str, str] = {},
                spare: Collection[str] = ()) -> tuple[State, dict[str, str]]:
    """The state over `names` (each bound to one of `objects`, THOR's metadata, as `bound` says where it says
    so; `spare` names after the others) and the binding."""
    return thor_state(objects, names, load_type_rules(), bound, spare)


@cache
def scene_objects(scene: str) -> tuple[Mapping, ...]:
    """A scene's objects at its start, as THOR's metadata has them."""
    return tuple(objects_metadata(scenes.load_scene(scene)))


def scene_names() -> list[str]:
    """The kitchens, FloorPlan1 first, in THOR's numeric order."""
    return scenes.scene_names()

