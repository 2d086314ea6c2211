"""One primitive atom of a plan, executed as THOR actions.

`pick_up(potato)` becomes: find the Potato's objectId, ask THOR where the
agent can stand to reach it (GetInteractablePoses), teleport there
(TeleportFull), then PickupObject. The paper assumes a *mise en place* kitchen
where the robot knows where everything is; teleporting is that assumption.

The executor does what the atom says and no more. A plan that puts an apple
it never picked up, or slices without a knife in hand, fails here with the
reason, instead of being silently repaired. THOR refusals come back with
THOR's own errorMessage.

Any object with a Controller's `step(action_dict)` and `last_event` is a
`Kitchen`: ai2thor's Controller on the embedded kitchen or on a real build.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from types import MappingProxyType
from typing import Any, Protocol

from cook2ltl import paths
from cook2ltl.domain.actions import WAIT, PrimitiveSet
from cook2ltl.ltl.ast import Atom
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.thor_types import liquids
from cook2ltl.world.thor_names import Binding, Obj, UnknownObject, by_id, held, objects_named, resolve

# Primitives of assets/primitives/ai2thor.toml that are one THOR interaction with their first argument.
INTERACTIONS = {
    "pick_up": "PickupObject",
    "open": "OpenObject",
    "close": "CloseObject",
    "break": "BreakObject",
    "cook": "CookObject",
    "slice": "SliceObject",
    "turn_on": "ToggleObjectOn",
    "turn_off": "ToggleObjectOff",
    "use": "UseUpObject",
    "empty": "EmptyLiquidFromObject",
}
TOGGLES = ("ToggleObjectOn", "ToggleObjectOff")
# The rest need more than one THOR call: put(what, where), drop(what) and fill(what, liquid) need the hand or
# a liquid; wait lets time pass. A test holds these against the set's file.
COMPOSED = ("put", "drop", "fill", WAIT)


def thor_primitives() -> PrimitiveSet:
    """The primitive set this executor runs: its names and parameters are assets/primitives/ai2thor.toml's."""
    return _thor_set(paths.assets_dir())


@cache
def _thor_set(assets: Path) -> PrimitiveSet:
    """Read once per assets folder: every rollout and kitchen check asks for it."""
    return load_primitives("ai2thor")


class Kitchen(Protocol):
    """What a rollout needs of ai2thor's Controller."""

    last_event: Any

    def step(self, action: Mapping[str, Any]) -> Any: ...

    def reset(self, scene: str) -> Any: ...


@dataclass(frozen=True)
class ThorCall:
    """One THOR action as sent, and THOR's answer."""

    action: Mapping[str, Any]
    success: bool
    error: str = ""

    def __post_init__(self) -> None:
        object.__setattr__(self, "action", MappingProxyType(dict(self.action)))


@dataclass(frozen=True)
class Attempt:
    """A primitive atom and what executing it took; `error` says why it failed."""

    atom: Atom
    calls: tuple[ThorCall, ...] = field(default=())
    success: bool = True
    error: str = ""


def execute(kitchen: Kitchen, atom: Atom, binding: Binding, preferred: frozenset[str] = frozenset()
            ) -> tuple[Attempt, Binding]:
    """Run one primitive atom; the attempt says how it went, the binding what was decided."""
    objects = kitchen.last_event.metadata["objects"]
    scene = kitchen.last_event.metadata.get("sceneName", "the kitchen").removesuffix("_physics")
    name, args = atom.name, atom.args
    if name == WAIT:
        return _run(kitchen, atom, [], {"action": "Pass"}), binding
    if name in ("put", "drop"):
        in_hand, problem = _in_hand(args[0], objects, binding)
        if problem:
            return Attempt(atom, success=False, error=f"{atom.text}: {problem}"), binding
        binding = binding if args[0] in binding.objects else binding.bind(args[0], in_hand)
        if name == "drop":
            return _run(kitchen, atom, [], {"action": "DropHandObject"}), binding
        target, binding = resolve(args[1], objects, binding, preferred, scene)
        calls, binding = _walk(kitchen, target, binding)
        return _run(kitchen, atom, calls, {"action": "PutObject", "objectId": target}), binding
    target, binding = resolve(args[0], objects, binding, preferred, scene)
    if name == "fill":
        if args[1] not in liquids():
            raise UnknownObject(f"No liquid {args[1]!r} in {scene}.", f"THOR fills with {', '.join(sorted(liquids()))}.")
        action = {"action": "FillObjectWithLiquid", "objectId": target, "fillLiquid": args[1]}
    else:
        action = {"action": INTERACTIONS[name], "objectId": target}
        if action["action"] in TOGGLES:
            action["objectId"] = _switch_of(target, objects)
    calls, binding = _walk(kitchen, action["objectId"], binding)
    return _run(kitchen, atom, calls, action), binding


def _in_hand(name: str, objects: Sequence[Obj], binding: Binding) -> tuple[str, str]:
    """The held object's id if it is what `name` stands for, else why not."""
    holding = held(objects)
    if holding is None:
        return "", f"the agent holds nothing; the plan must pick up {name} first"
    if holding["objectId"] not in {o["objectId"] for o in objects_named(name, objects, binding)}:
        return "", f"the agent holds {holding['objectId']}, not {name}"
    return holding["objectId"], ""


def _switch_of(target: str, objects: Sequence[Obj]) -> str:
    """THOR switches a stove burner with its knob: turning on a burner means turning its knob."""
    thing = by_id(objects, target)
    if thing is None or thing.get("toggleable"):
        return target
    knobs = sorted(o["objectId"] for o in objects if target in (o.get("controlledObjects") or ()))
    return knobs[0] if knobs else target


def _walk(kitchen: Kitchen, target: str, binding: Binding) -> tuple[list[ThorCall], Binding]:
    """Teleport to a pose from which `target` can be reached; nothing if already there.

    An object shut in a closed receptacle has no such pose; the agent then goes
    to the receptacle, and the action itself says what is wrong.
    """
    if binding.at == target:
        return [], binding
    objects = kitchen.last_event.metadata["objects"]
    thing = by_id(objects, target) or {}
    calls = []
    for place in (target, *(thing.get("parentReceptacles") or ())):
        call, metadata = send(kitchen, {"action": "GetInteractablePoses", "objectId": place})
        calls.append(call)
        poses = (metadata.get("actionReturn") or []) if call.success else []
        if poses:
            here = kitchen.last_event.metadata["agent"]["position"]
            pose = min(poses, key=lambda p: math.dist((p["x"], p["z"]), (here["x"], here["z"])))
            teleport = {
                "action": "TeleportFull",
                "position": {"x": pose["x"], "y": pose["y"], "z": pose["z"]},
                "rotation": {"x": 0.0, "y": pose["rotation"], "z": 0.0},
                "horizon": pose["horizon"],
                "standing": pose["standing"],
            }
            call, _ = send(kitchen, teleport)
            calls.append(call)
            return calls, binding.moved_to(target if call.success else None)
    return calls, binding.moved_to(None)


def _run(kitchen: Kitchen, atom: Atom, calls: list[ThorCall], action: dict[str, Any]) -> Attempt:
    call, _ = send(kitchen, action)
    return Attempt(atom, (*calls, call), call.success, "" if call.success else f"{atom.text}: {call.error}")


def send(kitchen: Kitchen, action: Mapping[str, Any]) -> tuple[ThorCall, Mapping[str, Any]]:
    """One THOR action; a refusal is an answer like any other, a dead kitchen is not (KitchenController raises)."""
    try:
        event = kitchen.step(dict(action))
    except ValueError:
        event = kitchen.last_event  # the Controller raises for argument errors after storing the answer
    metadata = event.metadata
    return ThorCall(action, bool(metadata["lastActionSuccess"]), metadata.get("errorMessage") or ""), metadata
