"""Agent positioning, THOR-style but without a floor plan: no collisions, no
reachability grid. Enough for an executor that teleports next to things, as the
paper's mise-en-place setting assumes."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace
from numbers import Real
from typing import Any

from cook2ltl.simulator.state import KitchenState, Refused, enclosing, is_held_or_carried

GRID_SIZE = 0.25  # THOR's default step, metres
ROTATE_DEGREES = 90.0
LOOK_DEGREES = 30.0
HORIZON_LIMITS = (-30.0, 60.0)  # THOR's default agent: looking up is negative
REACH = 0.75  # metres between an interactable pose and the object
POSE_HORIZON = 30.0  # looking down at a counter


def _number(action: Mapping[str, Any], key: str, default: float) -> float:
    value = action.get(key, default)
    if isinstance(value, bool) or not isinstance(value, Real):
        raise Refused(f"{key} must be a number, got {value!r}", "InvalidArgument")
    return float(value)


def _position(action: Mapping[str, Any], current) -> tuple[float, float, float]:
    given = action.get("position")
    if given is None:  # older THOR clients pass x, y, z at the top level
        given = {k: action[k] for k in "xyz" if k in action}
    if not isinstance(given, Mapping):
        raise Refused(f"position must be a dict with x, y, z, got {given!r}", "InvalidArgument")
    return tuple(_number(given, axis, current[i]) for i, axis in enumerate("xyz"))


def _rotation(action: Mapping[str, Any], current: float) -> float:
    given = action.get("rotation", {"y": current})
    if not isinstance(given, Mapping):
        raise Refused(f"rotation must be a dict with y, got {given!r}", "InvalidArgument")
    return _number(given, "y", current) % 360.0


def teleport(state: KitchenState, action):
    agent = state.agent
    moved = replace(
        agent,
        position=_position(action, agent.position),
        rotation=_rotation(action, agent.rotation),
        horizon=_number(action, "horizon", agent.horizon),
        standing=bool(action.get("standing", agent.standing)),
    )
    return state.evolve(agent=moved), None


def teleport_full(state: KitchenState, action):
    missing = [k for k in ("position", "rotation", "horizon", "standing") if k not in action]
    if missing:
        raise Refused(f"TeleportFull needs {', '.join(missing)}", "MissingArguments")
    return teleport(state, action)


def _move(right: float, ahead: float):
    def move(state: KitchenState, action):
        step = _number(action, "moveMagnitude", GRID_SIZE)
        yaw = math.radians(state.agent.rotation)
        x, y, z = state.agent.position
        # THOR's yaw 0 faces +z and 90 faces +x.
        dx = step * (ahead * math.sin(yaw) + right * math.cos(yaw))
        dz = step * (ahead * math.cos(yaw) - right * math.sin(yaw))
        return state.evolve(agent=replace(state.agent, position=(x + dx, y, z + dz))), None

    return move


def _rotate(sign: float):
    def rotate(state: KitchenState, action):
        degrees = _number(action, "degrees", ROTATE_DEGREES)
        yaw = (state.agent.rotation + sign * degrees) % 360.0
        return state.evolve(agent=replace(state.agent, rotation=yaw)), None

    return rotate


def _look(sign: float):
    def look(state: KitchenState, action):
        horizon = state.agent.horizon + sign * _number(action, "degrees", LOOK_DEGREES)
        low, high = HORIZON_LIMITS
        if not low <= horizon <= high:
            raise Refused(f"The camera cannot tilt to horizon {horizon:g} (limits {low:g} to {high:g})")
        return state.evolve(agent=replace(state.agent, horizon=horizon)), None

    return look


def interactable_poses(state: KitchenState, action):
    """THOR's GetInteractablePoses: where the agent can stand to act on the object.

    Without a floor plan the poses are the four sides of the object at arm's
    reach, facing it; as in THOR, an object shut in a closed receptacle has none.
    """
    object_id = action.get("objectId")
    if not object_id:
        raise Refused("GetInteractablePoses needs an objectId", "MissingArguments")
    thing = state.thing(object_id)
    if thing is None:
        raise Refused(f"No object with objectId {object_id!r} in {state.scene}")
    agent = state.agent
    if is_held_or_carried(state, object_id):
        x, y, z = agent.position
        return state, [_pose(x, y, z, agent.rotation, agent.horizon, agent.standing)]
    if enclosing(state, object_id) is not None:
        return state, []
    ox, _, oz = thing.position
    y = agent.position[1]
    poses = []
    for dx, dz in ((0.0, -REACH), (REACH, 0.0), (0.0, REACH), (-REACH, 0.0)):
        facing = math.degrees(math.atan2(-dx, -dz)) % 360.0  # THOR's yaw: 0 faces +z, 90 faces +x
        poses.append(_pose(ox + dx, y, oz + dz, facing, POSE_HORIZON, True))
    return state, poses


def _pose(x: float, y: float, z: float, rotation: float, horizon: float, standing: bool) -> dict[str, Any]:
    return {"x": x, "y": y, "z": z, "rotation": rotation, "standing": standing, "horizon": horizon}


def _no_op(state: KitchenState, action):
    return state, None


AGENT_ACTIONS = {
    "Teleport": teleport,
    "TeleportFull": teleport_full,
    "GetInteractablePoses": interactable_poses,
    "MoveAhead": _move(0.0, 1.0),
    "MoveBack": _move(0.0, -1.0),
    "MoveRight": _move(1.0, 0.0),
    "MoveLeft": _move(-1.0, 0.0),
    "RotateRight": _rotate(1.0),
    "RotateLeft": _rotate(-1.0),
    "LookDown": _look(1.0),
    "LookUp": _look(-1.0),
    "Pass": _no_op,
    "Done": _no_op,
}
