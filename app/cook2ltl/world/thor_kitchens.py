"""The AI2-THOR kitchens as world-model states: a scene's objects as THOR reports them, the names of a recipe bound
to them (`thor.thor_state`)."""

from __future__ import annotations

from collections.abc import Collection, Iterable, Mapping, Sequence
from functools import cache

from cook2ltl.simulator.metadata import objects_metadata
from cook2ltl.simulator.scenes import load_scene
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
    return tuple(objects_metadata(load_scene(scene)))

