"""Shared helpers for the kitchen tests: a `bench` that applies actions to a
scene's state and checks them, and a sandboxed HOME for anything that starts
ai2thor's Controller (it writes ~/.ai2thor and prunes releases there)."""

from __future__ import annotations

import pytest

from cook2ltl.simulator import rules
from cook2ltl.simulator.scenes import load_scene
from cook2ltl.simulator.state import KitchenState, Thing


class Bench:
    """A kitchen state plus assertions: `do` must succeed, `refuse` must fail and change nothing."""

    def __init__(self, scene: str = "FloorPlan1") -> None:
        self.state: KitchenState = load_scene(scene)

    def id(self, object_type: str) -> str:
        """The first object of this type in the scene (ids are THOR's, e.g. 'Apple|-00.47|+01.15|+00.48')."""
        return next(oid for oid, t in self.state.objects.items() if t.object_type == object_type)

    def __getitem__(self, object_type_or_id: str) -> Thing:
        key = object_type_or_id if "|" in object_type_or_id else self.id(object_type_or_id)
        return self.state.objects[key]

    def do(self, action: str, target: str | None = None, **args) -> rules.Result:
        result = rules.apply(self.state, self._action(action, target, args))
        assert result.success, f"{action} {target}: {result.error_message}"
        self.state = result.state
        return result

    def refuse(self, action: str, target: str | None = None, match: str = "", code: str = "", **args) -> rules.Result:
        before = self.state
        result = rules.apply(before, self._action(action, target, args))
        assert not result.success, f"{action} {target} should have failed"
        assert result.state is before, "a failed action must leave the state untouched"
        assert match.lower() in result.error_message.lower(), result.error_message
        assert result.error_code == code
        return result

    def hold(self, object_type_or_id: str) -> None:
        """Put whatever is held on the floor, then pick this up (opening what encloses it)."""
        if self.state.held:
            self.do("DropHandObject")
        self.do("PickupObject", self[object_type_or_id].object_id, forceAction=True)

    def _action(self, action: str, target: str | None, args: dict) -> dict:
        if target is not None:
            args["objectId"] = target if "|" in target else self.id(target)
        return {"action": action, **args}


@pytest.fixture
def bench() -> Bench:
    return Bench("FloorPlan1")


@pytest.fixture
def bench_in():
    """A bench for another scene: bench_in("FloorPlan2")."""
    return Bench
