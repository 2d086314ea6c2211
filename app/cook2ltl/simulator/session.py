"""One Controller's session with the embedded kitchen: the build-level actions
(Reset, Initialize, GetScenesInBuild, ChangeResolution, ...) around the rules,
and the THOR event envelope around every answer."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from cook2ltl.simulator import rules, scenes
from cook2ltl.simulator.metadata import agent_metadata, objects_metadata, xyz
from cook2ltl.simulator.state import KitchenState, Refused

# What THOR's Initialize returns and the Controller reads back (Server.set_init_params).
CAMERA_PLANES = {"cameraNearPlane": 0.1, "cameraFarPlane": 20.0}


@dataclass
class Session:
    """Mutable by design: the player's loop owns exactly one and feeds it actions."""

    width: int = 300
    height: int = 300
    state: KitchenState | None = None
    slice_needs_knife: bool = True

    def first_event(self) -> dict[str, Any]:
        """What a THOR build sends once its pipes are open, before any action."""
        return self._envelope({"action": "", "sequenceId": 0}, rules.Result(self.state, True, ""))

    def handle(self, action: dict[str, Any]) -> dict[str, Any]:
        name = action.get("action")
        build_action = _BUILD_ACTIONS.get(name)
        try:
            if build_action is not None:
                returned = build_action(self, action)  # may replace self.state
                result = rules.Result(self.state, True, "", returned)
            elif self.state is None:
                result = rules.Result(None, False, f"{name}: no scene is loaded yet; reset to a scene first")
            else:
                result = rules.apply(self.state, action)
        except Refused as refusal:
            result = rules.Result(self.state, False, refusal.message, None, refusal.code)
        answer = self._envelope(action, result)
        # Kept only once it reads back: if not, the player reports the failure on the old state and lives.
        self.state = result.state
        return answer

    def failure(self, action: dict[str, Any], message: str) -> dict[str, Any]:
        """A failed answer to `action` that leaves the kitchen as it was."""
        return self._envelope(action, rules.Result(self.state, False, message))

    def _envelope(self, action: dict[str, Any], result: rules.Result) -> dict[str, Any]:
        state = result.state
        held = state and state.held and state.objects[state.held]
        agent = {
            "agentId": 0,
            "sequenceId": action.get("sequenceId", 0),
            "sceneName": f"{state.scene}_physics" if state else "",
            "lastAction": action.get("action", ""),
            "lastActionSuccess": result.success,
            "errorMessage": result.error_message,
            "errorCode": result.error_code,
            "actionReturn": result.action_return,
            "objects": objects_metadata(state) if state else [],
            "agent": agent_metadata(state) if state else None,
            "inventoryObjects": [{"objectId": held.object_id, "objectType": held.object_type}] if held else [],
            "screenWidth": self.width,
            "screenHeight": self.height,
            "fov": 90.0,
            "cameraPosition": xyz(state.agent.position) if state else None,
            "isSceneAtRest": True,
            "collided": False,
            "collidedObjects": [],
            "thirdPartyCameras": [],
        }
        return {
            "agents": [agent],
            "sequenceId": agent["sequenceId"],
            "activeAgentId": 0,
            "thirdPartyCameras": [],
        }


def _reset(session: Session, action: dict[str, Any]) -> None:
    try:
        fresh = scenes.load_scene(action.get("sceneName", ""))
    except scenes.UnknownScene as err:
        raise Refused(str(err), "InvalidArgument") from None
    session.state = fresh.evolve(slice_needs_knife=session.slice_needs_knife)


def _initialize(session: Session, action: dict[str, Any]) -> dict[str, float]:
    if session.state is None:
        raise Refused("Initialize: no scene is loaded yet; reset to a scene first")
    # Our own switch (not a THOR parameter): whether SliceObject needs a knife in hand.
    session.slice_needs_knife = bool(action.get("sliceNeedsKnife", session.slice_needs_knife))
    session.state = session.state.evolve(slice_needs_knife=session.slice_needs_knife)
    return CAMERA_PLANES


def _scenes_in_build(session: Session, action: dict[str, Any]) -> list[str]:
    return [f"{name}_physics" for name in scenes.scene_names()]


def _change_resolution(session: Session, action: dict[str, Any]) -> None:
    x, y = action.get("x"), action.get("y")
    if not (isinstance(x, int) and isinstance(y, int) and x > 0 and y > 0):
        raise Refused(f"ChangeResolution needs positive integers x and y, got {x!r}, {y!r}", "InvalidArgument")
    session.width, session.height = x, y


def _accept(session: Session, action: dict[str, Any]) -> None:
    return None


_BUILD_ACTIONS = {
    "Reset": _reset,
    "Initialize": _initialize,
    "GetScenesInBuild": _scenes_in_build,
    "ChangeResolution": _change_resolution,
    "ChangeQuality": _accept,  # no rendering, so nothing to change
}
