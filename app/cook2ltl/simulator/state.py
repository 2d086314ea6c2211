"""The kitchen's state as immutable values, and the questions the rules ask of it.

A `KitchenState` is never changed in place: the rules build a new one for every
successful action, so a failed action trivially leaves the old state untouched.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType

from cook2ltl.thor_types import TypeRules

Vec3 = tuple[float, float, float]

# THOR's capability flags, kept per object as a set of names.
ABILITIES = (
    "pickupable",
    "receptacle",
    "openable",
    "toggleable",
    "sliceable",
    "cookable",
    "canFillWithLiquid",
    "dirtyable",
    "breakable",
    "canBeUsedUp",
    "isHeatSource",
    "isColdSource",
    "moveable",
)


class Refused(Exception):
    """A rule refused an action; `code` is THOR's errorCode when the arguments were at fault."""

    def __init__(self, message: str, code: str = "") -> None:
        super().__init__(message)
        self.message = message
        self.code = code


@dataclass(frozen=True)
class Thing:
    """One THOR SimObject: identity, abilities and the state that actions change."""

    object_id: str
    object_type: str
    name: str
    position: Vec3
    abilities: frozenset[str]
    parent: str | None = None
    controlled: tuple[str, ...] | None = None
    is_open: bool = False
    openness: float = 0.0
    is_toggled: bool = False
    is_cooked: bool = False
    is_filled: bool = False
    fill_liquid: str | None = None
    is_dirty: bool = False
    is_broken: bool = False
    is_used_up: bool = False
    temperature: str = "RoomTemp"

    def can(self, ability: str) -> bool:
        return ability in self.abilities


@dataclass(frozen=True)
class Agent:
    position: Vec3 = (0.0, 0.9, 0.0)
    rotation: float = 0.0  # yaw in degrees
    horizon: float = 0.0
    standing: bool = True


@dataclass(frozen=True)
class KitchenState:
    scene: str
    objects: Mapping[str, Thing]
    types: TypeRules
    agent: Agent = field(default_factory=Agent)
    held: str | None = None
    slice_needs_knife: bool = True

    def __post_init__(self) -> None:
        # Freeze the mapping so a state can be shared without defensive copies.
        if not isinstance(self.objects, MappingProxyType):
            object.__setattr__(self, "objects", MappingProxyType(dict(self.objects)))
        # A rule that removes the held object is a kitchen bug: fail the action, not the metadata after it.
        if self.held is not None and self.held not in self.objects:
            raise ValueError(f"the agent would hold {self.held}, which is no longer in {self.scene}")

    def thing(self, object_id: str) -> Thing | None:
        return self.objects.get(object_id)

    def with_things(self, *changed: Thing, removed: tuple[str, ...] = ()) -> dict[str, Thing]:
        """A fresh object table with `changed` replaced or added and `removed` dropped."""
        table = {oid: t for oid, t in self.objects.items() if oid not in removed}
        for thing in changed:
            table[thing.object_id] = thing
        return table

    def evolve(self, **changes) -> KitchenState:
        return replace(self, **changes)


def ancestors(state: KitchenState, object_id: str) -> Iterator[Thing]:
    """The receptacles holding `object_id`, nearest first."""
    seen = {object_id}
    thing = state.objects[object_id]
    while thing.parent is not None and thing.parent not in seen:
        seen.add(thing.parent)
        thing = state.objects[thing.parent]
        yield thing


def contents(state: KitchenState, receptacle_id: str) -> list[str]:
    """Everything inside `receptacle_id`, however deep, in scene order."""
    return [oid for oid in state.objects if any(a.object_id == receptacle_id for a in ancestors(state, oid))]


def is_held_or_carried(state: KitchenState, object_id: str) -> bool:
    """True for the held object and anything riding inside it."""
    if state.held is None:
        return False
    return object_id == state.held or any(a.object_id == state.held for a in ancestors(state, object_id))


def enclosing(state: KitchenState, object_id: str) -> Thing | None:
    """The closed openable receptacle that shuts `object_id` away, if any."""
    for outer in ancestors(state, object_id):
        if outer.can("openable") and not outer.is_open:
            return outer
    return None
