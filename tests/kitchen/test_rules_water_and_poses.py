"""What the rollout executor relies on beyond the first kitchen rules: THOR's GetInteractablePoses, a running
faucet rinsing and filling what is in the sink basin, and UseUpObject."""

import math
from dataclasses import replace

import pytest

from cook2ltl.simulator.agent import REACH

FAUCET = "Faucet|-02.15|+00.91|-01.50"
BASIN = "Sink|-01.90|+00.97|-01.50|SinkBasin"
FRIDGE = "Fridge|-02.10|+00.00|+01.07"


def test_interactable_poses_face_the_object_at_arms_reach(bench):
    apple = bench["Apple"]
    poses = bench.do("GetInteractablePoses", "Apple").action_return
    assert len(poses) == 4
    for pose in poses:
        assert set(pose) == {"x", "y", "z", "rotation", "standing", "horizon"}
        assert math.dist((pose["x"], pose["z"]), (apple.position[0], apple.position[2])) == pytest.approx(REACH)
        yaw = math.radians(pose["rotation"])  # THOR: 0 faces +z, 90 faces +x
        ahead = (pose["x"] + REACH * math.sin(yaw), pose["z"] + REACH * math.cos(yaw))
        assert ahead == pytest.approx((apple.position[0], apple.position[2]), abs=1e-6)


def test_no_pose_reaches_into_a_closed_fridge(bench):
    assert bench.do("GetInteractablePoses", "Egg").action_return == []
    bench.do("OpenObject", FRIDGE)
    assert len(bench.do("GetInteractablePoses", "Egg").action_return) == 4
    bench.refuse("GetInteractablePoses", match="needs an objectId", code="MissingArguments")


def test_a_running_faucet_rinses_and_fills_what_is_in_the_basin(bench):
    bench.do("DirtyObject", "Mug", forceAction=True)
    bench.hold("Mug")
    bench.do("PutObject", BASIN)
    assert bench["Mug"].is_dirty and not bench["Mug"].is_filled
    bench.do("ToggleObjectOn", FAUCET)
    assert not bench["Mug"].is_dirty and bench["Mug"].fill_liquid == "water"
    assert not bench["Apple"].is_dirty and bench["Apple"].temperature == "RoomTemp"  # elsewhere, nothing happens


def test_a_dry_basin_cleans_nothing(bench):
    bench.do("DirtyObject", "Mug", forceAction=True)
    bench.hold("Mug")
    bench.do("PutObject", BASIN)
    bench.do("Pass")
    assert bench["Mug"].is_dirty


def test_use_up_object(bench):
    bench.refuse("UseUpObject", "PaperTowelRoll", match="cannot be used up")
    roll = bench["PaperTowelRoll"]  # no kitchen object can be used up in the scenes; THOR's paper towels can
    bench.state = bench.state.evolve(objects=bench.state.with_things(
        replace(roll, abilities=roll.abilities | {"canBeUsedUp"})))
    bench.do("UseUpObject", "PaperTowelRoll")
    assert bench["PaperTowelRoll"].is_used_up
    bench.refuse("UseUpObject", "PaperTowelRoll", match="already used up")
