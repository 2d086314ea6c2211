"""Agent positioning, and the 30 kitchens as loaded from assets/kitchens/."""

import pytest

from cook2ltl.simulator.scenes import UnknownScene, canonical_scene, load_scene, scene_names
from cook2ltl.simulator.state import ancestors
from cook2ltl.thor_types import load_type_rules


def test_teleport_and_teleport_full(bench):
    bench.do("Teleport", position={"x": 1.0, "y": 0.9, "z": -1.5}, rotation={"y": 270})
    agent = bench.state.agent
    assert agent.position == (1.0, 0.9, -1.5) and agent.rotation == 270.0
    bench.refuse("TeleportFull", match="needs rotation, horizon, standing", code="MissingArguments", position={})
    bench.refuse("Teleport", match="must be a number", code="InvalidArgument", horizon="level")


def test_moves_follow_the_heading(bench):
    bench.do("Teleport", position={"x": 0.0, "y": 0.9, "z": 0.0}, rotation={"y": 90})
    bench.do("MoveAhead")
    x, _, z = bench.state.agent.position
    assert x == pytest.approx(0.25) and z == pytest.approx(0.0, abs=1e-9)
    bench.do("RotateLeft")
    assert bench.state.agent.rotation == 0.0


def test_the_camera_tilts_within_limits(bench):
    bench.do("LookDown")
    bench.do("LookDown")
    assert bench.state.agent.horizon == 60.0
    bench.refuse("LookDown", match="cannot tilt")


def test_all_thirty_kitchens_load():
    names = scene_names()
    assert names == [f"FloorPlan{n}" for n in range(1, 31)]
    for name in names:
        state = load_scene(name)
        assert state.scene == name and len(state.objects) > 50
        for thing in state.objects.values():
            list(ancestors(state, thing.object_id))  # every parent exists


def test_starting_placements_respect_the_receptacle_table():
    types = load_type_rules()
    for name in scene_names():
        state = load_scene(name)
        for thing in state.objects.values():
            if thing.can("pickupable") and thing.parent:
                parent = state.objects[thing.parent].object_type
                assert types.fits(thing.object_type, parent), (name, thing.object_id, parent)


def test_every_sliceable_type_has_a_slicing_rule():
    slicing = load_type_rules().slicing
    for name in scene_names():
        for thing in load_scene(name).objects.values():
            if thing.can("sliceable"):
                assert thing.object_type in slicing


def test_every_fridge_is_a_cold_source():
    fridge = next(t for t in load_scene("FloorPlan28").objects.values() if t.object_type == "Fridge")
    assert fridge.can("isColdSource")


def test_scene_names_are_normalised_and_checked():
    assert canonical_scene("FloorPlan7_physics") == "FloorPlan7"
    with pytest.raises(UnknownScene, match="FloorPlan1, FloorPlan2"):
        canonical_scene("FloorPlan301")


def test_a_name_no_type_has_stands_for_its_head_noun():
    from cook2ltl.world.thor_names import types_for

    assert types_for("dirty_plate", {"Plate", "Mug"}) == ("Plate",)
    assert types_for("wine_bottle", {"WineBottle", "Bottle"}) == ("WineBottle",)  # the whole name first
    assert types_for("blue_zebra", {"Plate"}) == ()
