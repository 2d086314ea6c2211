"""Render a KitchenState as THOR event metadata: the same keys an AI2-THOR build
sends, so code written against `event.metadata["objects"]` works unchanged.

Fields THOR fills from geometry the kitchen does not have (bounding boxes,
mass, materials) are left out rather than faked.
"""

from __future__ import annotations

import math
from collections import defaultdict
from typing import Any

from cook2ltl.simulator.state import KitchenState, Thing, ancestors

HAND_REACH = 0.5  # metres in front of the agent where a held object is reported


def hand_position(state: KitchenState) -> tuple[float, float, float]:
    x, y, z = state.agent.position
    yaw = math.radians(state.agent.rotation)
    return (x + HAND_REACH * math.sin(yaw), y, z + HAND_REACH * math.cos(yaw))


def agent_metadata(state: KitchenState) -> dict[str, Any]:
    agent = state.agent
    return {
        "name": "agent",
        "position": xyz(agent.position),
        "rotation": {"x": 0.0, "y": agent.rotation, "z": 0.0},
        "cameraHorizon": agent.horizon,
        "isStanding": agent.standing,
        "inHighFrictionArea": False,
    }


def objects_metadata(state: KitchenState) -> list[dict[str, Any]]:
    chains = {oid: list(ancestors(state, oid)) for oid in state.objects}
    inside: dict[str, list[str]] = defaultdict(list)
    for oid, chain in chains.items():
        for outer in chain:
            inside[outer.object_id].append(oid)
    hand = hand_position(state)
    out = []
    for oid, thing in state.objects.items():
        chain = chains[oid]
        carried = state.held is not None and (oid == state.held or any(a.object_id == state.held for a in chain))
        shut_in = any(a.can("openable") and not a.is_open for a in chain)
        position = hand if carried else thing.position
        out.append(
            _object(
                thing,
                position=position,
                distance=math.dist(state.agent.position, position),
                visible=not shut_in,
                picked_up=oid == state.held,
                contents=inside.get(oid, []),
                parents=[a.object_id for a in chain],
            )
        )
    return out


def _object(thing: Thing, *, position, distance, visible, picked_up, contents, parents) -> dict[str, Any]:
    can = thing.can
    return {
        "objectId": thing.object_id,
        "objectType": thing.object_type,
        "name": thing.name,
        "position": xyz(position),
        "rotation": {"x": 0.0, "y": 0.0, "z": 0.0},
        "visible": visible,
        "isInteractable": visible,
        "distance": distance,
        "receptacle": can("receptacle"),
        "receptacleObjectIds": contents if can("receptacle") else None,
        "parentReceptacles": parents or None,
        "pickupable": can("pickupable"),
        "isPickedUp": picked_up,
        "moveable": can("moveable"),
        "isMoving": False,
        "openable": can("openable"),
        "isOpen": thing.is_open,
        "openness": thing.openness,
        "toggleable": can("toggleable"),
        "isToggled": thing.is_toggled,
        "sliceable": can("sliceable"),
        "isSliced": False,  # a sliced object is replaced by its pieces, as in THOR
        "cookable": can("cookable"),
        "isCooked": thing.is_cooked,
        "breakable": can("breakable"),
        "isBroken": thing.is_broken,
        "canFillWithLiquid": can("canFillWithLiquid"),
        "isFilledWithLiquid": thing.is_filled,
        "fillLiquid": thing.fill_liquid,
        "dirtyable": can("dirtyable"),
        "isDirty": thing.is_dirty,
        "canBeUsedUp": can("canBeUsedUp"),
        "isUsedUp": thing.is_used_up,
        "temperature": thing.temperature,
        "isHeatSource": can("isHeatSource"),
        "isColdSource": can("isColdSource"),
        "controlledObjects": list(thing.controlled) if thing.controlled is not None else None,
    }


def xyz(v) -> dict[str, float]:
    return {"x": v[0], "y": v[1], "z": v[2]}
