"""One embedded kitchen behind ai2thor's own Controller for a whole test module (it starts in half a second
and resets in milliseconds), with HOME and the kitchen's script cache kept in a temp dir."""

from __future__ import annotations

import pytest

pytest.importorskip("ai2thor")


@pytest.fixture(scope="module")
def controller(thor_home):
    from cook2ltl.execution.launcher import start_embedded

    started = start_embedded("FloorPlan1")
    yield started
    player = started.server.unity_proc
    started.stop()
    assert player.poll() is not None  # no kitchen process left behind


@pytest.fixture
def kitchen(controller):
    """The module's Controller, reset to FloorPlan1; `kitchen.reset("FloorPlanN")` for another."""
    controller.reset("FloorPlan1")
    return controller
