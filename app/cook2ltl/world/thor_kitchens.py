"""The AI2-THOR kitchens as world-model states: a scene's objects as THOR reports them, the names of a recipe bound
to them (`thor.thor_state`), and the scene a recipe fits best when none is given."""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from functools import cache

from cook2ltl.world.logic import State


def scene_start(objects: Sequence[Mapping], names: Iterable[str]) -> tuple[State, dict[str, str]]:
    """The state over `names` (each bound to one of `objects`, THOR's metadata) and the binding."""
    from cook2ltl.kitchen.scenes import load_type_rules
    from cook2ltl.world.thor import thor_state

    return thor_state(objects, names, load_type_rules())


@cache
def scene_objects(scene: str) -> tuple[Mapping, ...]:
    """A scene's objects at its start, as THOR's metadata has them."""
    from cook2ltl.kitchen.metadata import objects_metadata
    from cook2ltl.kitchen.scenes import load_scene

    return tuple(objects_metadata(load_scene(scene)))


def best_scene(names: Iterable[str]) -> str:
    """The kitchen where most of the names find an object (ties: the lowest number)."""
    from cook2ltl.kitchen.names import known_types, types_for
    from cook2ltl.kitchen.scenes import scene_names

    wanted = list(dict.fromkeys(names))

    def score(scene: str) -> tuple[int, int]:
        available = known_types(scene_objects(scene))
        return (-sum(1 for n in wanted if types_for(n, available)), int(scene.removeprefix("FloorPlan")))

    return min(scene_names(), key=score)
