"""Load the 30 AI2-THOR kitchens and the object-type rules from assets/kitchens/.

The scene files hold real THOR object metadata (one JSON list per FloorPlan).
Their `parentReceptacles` list every receptacle an object touches, so an egg in
a fridge may also name the floor, and a pan may sit on two burners. The kitchen
needs one container per object; `_choose_parent` picks the most specific one.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import replace
from functools import cache
from pathlib import Path

from cook2ltl.paths import assets_dir
from cook2ltl.simulator.state import ABILITIES, Agent, KitchenState, Thing
from cook2ltl.thor_types import load_type_rules

_SCENE_NAME = re.compile(r"^(FloorPlan\d+)(?:_physics)?$")


class UnknownScene(ValueError):
    """The asked-for scene is not among the kitchens in assets/kitchens/scenes/."""


def kitchens_dir() -> Path:
    return assets_dir() / "kitchens"  # $COOK2LTL_ASSETS, checked as every path a user gives


def scene_names() -> list[str]:
    """The kitchens on disk, FloorPlan1 first, in THOR's numeric order."""
    names = [p.stem for p in (kitchens_dir() / "scenes").glob("FloorPlan*.json")]
    return sorted(names, key=lambda n: int(n.removeprefix("FloorPlan")))


def canonical_scene(name: str) -> str:
    """'FloorPlan1_physics' (what the THOR Controller sends) -> 'FloorPlan1'."""
    match = _SCENE_NAME.match(name or "")
    if not match or match.group(1) not in scene_names():
        known = ", ".join(scene_names()) or f"none found in {kitchens_dir() / 'scenes'}"
        raise UnknownScene(f"no kitchen scene named {name!r} (known: {known})")
    return match.group(1)


@cache
def load_scene(name: str) -> KitchenState:
    """The scene's starting state (cached: states are immutable, so sharing is safe)."""
    scene = canonical_scene(name)
    with open(kitchens_dir() / "scenes" / f"{scene}.json", encoding="utf-8") as f:
        records = json.load(f)
    things = [_thing(r) for r in records]
    by_id = {t.object_id: t for t in things}
    parents = _choose_parents(records, by_id)
    table = {t.object_id: _with_parent(t, parents.get(t.object_id)) for t in things}
    return KitchenState(
        scene=scene,
        objects=table,
        types=load_type_rules(),
        agent=Agent(position=_agent_start(things)),
    )


def _thing(r: dict) -> Thing:
    abilities = {a for a in ABILITIES if r.get(a)}
    # The source marks one fridge (FloorPlan28) as no cold source; every THOR fridge is one.
    if r["objectType"] == "Fridge":
        abilities.add("isColdSource")
    p = r["position"]
    return Thing(
        object_id=r["objectId"],
        object_type=r["objectType"],
        name=r["name"],
        position=(p["x"], p["y"], p["z"]),
        abilities=frozenset(abilities),
        controlled=tuple(r["controlledObjects"]) if r["controlledObjects"] is not None else None,
        is_open=bool(r["isOpen"]),
        openness=1.0 if r["isOpen"] else 0.0,
        is_toggled=bool(r["isToggled"]),
        is_cooked=bool(r["isCooked"]),
        is_filled=bool(r["isFilledWithLiquid"]),
        fill_liquid=r["fillLiquid"],
        is_dirty=bool(r["isDirty"]),
        is_broken=bool(r["isBroken"]),
        is_used_up=bool(r["isUsedUp"]),
        temperature=r["temperature"],
    )


def _with_parent(thing: Thing, parent: str | None) -> Thing:
    return thing if parent is None else replace(thing, parent=parent)


def _choose_parents(records: list[dict], by_id: dict[str, Thing]) -> dict[str, str]:
    """One container per object, most specific first, never forming a cycle.

    Fixtures (neither pickupable nor moveable: counters, cabinets, the floor)
    stay where they are and get no container. A pickupable container (plate,
    pot) can only hold pickupable things; a table never sits "in" a plate.
    """
    chosen: dict[str, str] = {}
    for r in records:
        thing = by_id[r["objectId"]]
        if not (thing.can("pickupable") or thing.can("moveable")):
            continue
        candidates = [by_id[c] for c in r["parentReceptacles"] or [] if c in by_id]
        if not thing.can("pickupable"):
            candidates = [c for c in candidates if not c.can("pickupable")]
        for parent in sorted(candidates, key=lambda c: _specificity(thing, c)):
            if not _leads_to(chosen, parent.object_id, thing.object_id):
                chosen[thing.object_id] = parent.object_id
                break
    return chosen


def _specificity(thing: Thing, candidate: Thing) -> tuple[int, float]:
    # A plate beats the counter under it, any counter beats the floor, and
    # among equals the nearest wins (a mug by the coffee machine is in it).
    tier = 0 if candidate.can("pickupable") else 2 if candidate.object_type == "Floor" else 1
    return tier, math.dist(thing.position, candidate.position)


def _leads_to(chosen: dict[str, str], start: str, target: str) -> bool:
    node: str | None = start
    while node is not None:
        if node == target:
            return True
        node = chosen.get(node)
    return False


def _agent_start(things: list[Thing]) -> tuple[float, float, float]:
    # The source has no agent pose: start in the middle of the counters, at THOR's eye height.
    counters = [t.position for t in things if t.object_type == "CounterTop"] or [t.position for t in things]
    x = sum(p[0] for p in counters) / len(counters)
    z = sum(p[2] for p in counters) / len(counters)
    return (round(x, 2), 0.9, round(z, 2))
