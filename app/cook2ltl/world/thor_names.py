"""The names a plan uses (`potato`, `stove_burner`) and the THOR objects they stand for.

A name matches an object type when both read the same without underscores and
case (`stove_burner` ~ StoveBurner, `countertop` ~ CounterTop); a few kitchen
words have fixed stand-ins (`sink` is the SinkBasin things go in, `knife` may be
a ButterKnife). Slicing replaces an object by pieces whose ids extend its own
(`Tomato|…|TomatoSliced_0`), so a name keeps standing for what was cut.

Everything here reads THOR event metadata (`event.metadata["objects"]`), so it
works the same on the embedded kitchen and on a real AI2-THOR build.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any

from cook2ltl.errors import UserError
from cook2ltl.thor_types import load_type_rules

Obj = Mapping[str, Any]  # one entry of event.metadata["objects"]

# Kitchen words whose THOR object is not the type of the same name, in order of preference.
STAND_INS = {
    "sink": ("SinkBasin", "Sink"),
    "knife": ("Knife", "ButterKnife"),
    "stove": ("StoveBurner",),
    "stovetop": ("StoveBurner",),
    "burner": ("StoveBurner",),
    "counter": ("CounterTop",),
    "refrigerator": ("Fridge",),
    "tap": ("Faucet",),
}


class UnknownObject(UserError):
    """A plan names something the kitchen does not have."""


@dataclass(frozen=True)
class Binding:
    """What the rollout has decided so far: the object each name stands for, and
    the object the agent last went to (so it does not walk to it twice)."""

    objects: Mapping[str, str] = field(default_factory=dict)
    at: str | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "objects", MappingProxyType(dict(self.objects)))

    def bind(self, name: str, object_id: str) -> Binding:
        return replace(self, objects={**self.objects, name: object_id})

    def moved_to(self, object_id: str | None) -> Binding:
        return replace(self, at=object_id)


def key(name: str) -> str:
    return name.replace("_", "").lower()


def snake_case(object_type: str) -> str:
    """StoveBurner -> stove_burner: how the primitive sets write THOR types."""
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", object_type).lower()


def piece_types() -> dict[str, str]:
    """Object type -> the type of its pieces once sliced (Tomato -> TomatoSliced, Egg -> EggCracked)."""
    return {whole: rule.into for whole, rule in load_type_rules().slicing.items()}


def types_for(name: str, available: set[str]) -> tuple[str, ...]:
    """The object types `name` may stand for, best first, among `available`; a name no type has stands for what
    its head noun does (the last word: a dirty_plate is a plate, salted_water is water)."""
    wanted = STAND_INS.get(key(name)) or tuple(t for t in available if key(t) == key(name))
    found = tuple(t for t in wanted if t in available)
    return found or (types_for(name.rsplit("_", 1)[1], available) if "_" in name.strip("_") else ())


def scene_names(objects: Sequence[Obj]) -> list[str]:
    """The kitchen's object types, in snake_case."""
    return sorted({snake_case(o["objectType"]) for o in objects})


def known_types(objects: Sequence[Obj]) -> set[str]:
    """The types present, and the types of the pieces they can be cut into."""
    types = {o["objectType"] for o in objects}
    pieces = piece_types()
    return types | {pieces[t] for t in types if t in pieces}


def check_names(names: Sequence[str], objects: Sequence[Obj], scene: str) -> None:
    """UnknownObject naming every name that stands for nothing in this kitchen."""
    available = known_types(objects)
    unknown = sorted({n for n in names if not types_for(n, available)})
    if unknown:
        listed = ", ".join(scene_names(objects))
        noun = "object" if len(unknown) == 1 else "objects"
        raise UnknownObject(
            f"No {noun} {', '.join(repr(n) for n in unknown)} in {scene}.",
            f"the kitchen has: {listed}.",
        )


def objects_named(name: str, objects: Sequence[Obj], binding: Binding) -> list[Obj]:
    """The objects `name` stands for now: its bound object, or the pieces it was
    cut into; when unbound, every object of a matching type or their pieces."""
    bound = binding.objects.get(name)
    if bound is not None:
        return [o for o in objects if o["objectId"] == bound or o["objectId"].startswith(bound + "|")]
    types = types_for(name, known_types(objects))
    pieces = piece_types()
    wanted = set(types) | {pieces[t] for t in types if t in pieces}
    return [o for o in objects if o["objectType"] in wanted]


def resolve(name: str, objects: Sequence[Obj], binding: Binding, preferred: frozenset[str] = frozenset(),
            scene: str = "the kitchen") -> tuple[str, Binding]:
    """The objectId `name` stands for, and the binding that remembers it.

    Among several candidates: the one in hand, then one not already cut, then
    one the task's goal names, then one that switches or holds something
    already bound (the knob of the burner in use, the burner under the pan),
    then one not shut away, then the first type for the name, then the nearer.
    """
    candidates = objects_named(name, objects, binding)
    if not candidates:
        check_names([name], objects, scene)  # raises for a name the kitchen lacks
        raise UnknownObject(f"{name!r} is gone from {scene}: nothing of it is left.",
                            "a plan cannot use what it has used up or thrown away.")
    types = types_for(name, known_types(objects))
    bound = set(binding.objects.values())
    shut = shut_away(objects)

    def rank(o: Obj) -> tuple:
        related = bool((set(o.get("controlledObjects") or ()) | set(o.get("receptacleObjectIds") or ())) & bound)
        kind = types.index(o["objectType"]) if o["objectType"] in types else len(types)
        # A real THOR build may keep a cut object beside its pieces, flagged isSliced: the pieces come first.
        return (not o.get("isPickedUp"), bool(o.get("isSliced")), o["objectId"] not in preferred, not related,
                o["objectId"] in shut, kind, o.get("distance", 0.0), o["objectId"])

    chosen = min(candidates, key=rank)["objectId"]
    if name in binding.objects:
        return chosen, binding  # a piece of what the name was bound to
    return chosen, binding.bind(name, chosen)


def shut_away(objects: Sequence[Obj]) -> set[str]:
    """Ids of the objects inside a closed receptacle (THOR cannot see or reach them)."""
    closed = {o["objectId"] for o in objects if o.get("openable") and not o.get("isOpen")}
    return {o["objectId"] for o in objects if closed & set(o.get("parentReceptacles") or ())}


def held(objects: Sequence[Obj]) -> Obj | None:
    return next((o for o in objects if o.get("isPickedUp")), None)


def by_id(objects: Sequence[Obj], object_id: str) -> Obj | None:
    return next((o for o in objects if o["objectId"] == object_id), None)
