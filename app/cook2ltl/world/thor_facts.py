"""State predicates read off THOR metadata: `hot(potato)`, `sliced(tomato)`, `filled(mug)`.

After every action the rollout asks which of the formula's predicate atoms
hold; those join the action in the step that progression sees. A predicate
holds of a name when it holds of any object the name stands for (the potato,
or one of its slices). The kitchen has no clock, so a wait step stands for any
duration: `elapsed(30_minutes)` holds at a step where the agent waited.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence

from cook2ltl.ltl.ast import Atom
from cook2ltl.world.thor_names import Binding, Obj, objects_named, piece_types

ELAPSED = "elapsed"


def _sliced(o: Obj) -> bool:
    return bool(o.get("isSliced")) or o["objectType"] in set(piece_types().values())


# One argument, the name of the object: the ai2thor primitive set's states, and THOR's other flags.
PREDICATES: dict[str, Callable[[Obj], bool]] = {
    "hot": lambda o: o.get("temperature") == "Hot",
    "cold": lambda o: o.get("temperature") == "Cold",
    "room_temperature": lambda o: o.get("temperature") == "RoomTemp",
    "cooked": lambda o: bool(o.get("isCooked")),
    "sliced": _sliced,
    "broken": lambda o: bool(o.get("isBroken")),
    "filled": lambda o: bool(o.get("isFilledWithLiquid")),
    "used_up": lambda o: bool(o.get("isUsedUp")),
    "dirty": lambda o: bool(o.get("isDirty")),
    "clean": lambda o: o.get("dirtyable", False) and not o.get("isDirty"),
    "open": lambda o: bool(o.get("isOpen")),
    "closed": lambda o: o.get("openable", False) and not o.get("isOpen"),
    "on": lambda o: bool(o.get("isToggled")),
    "off": lambda o: o.get("toggleable", False) and not o.get("isToggled"),
}


def observable(atom: Atom) -> bool:
    """Whether the kitchen can ever tell if `atom` holds (`boiled(egg)` it cannot)."""
    if atom.name == ELAPSED:
        return len(atom.args) == 1
    return atom.name in PREDICATES and len(atom.args) == 1


def true_facts(predicates: Iterable[Atom], objects: Sequence[Obj], binding: Binding, waited: bool) -> frozenset[Atom]:
    """The predicate atoms among `predicates` that hold in this state."""
    found = set()
    for atom in predicates:
        if atom.name == ELAPSED:
            if waited and observable(atom):
                found.add(atom)
        elif observable(atom):
            test = PREDICATES[atom.name]
            if any(test(o) for o in objects_named(atom.args[0], objects, binding)):
                found.add(atom)
    return frozenset(found)
