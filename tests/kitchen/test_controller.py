"""End to end: ai2thor's own, unmodified Controller driving the embedded kitchen
over its FIFO protocol, including the paper's four AI2-THOR tasks."""

import statistics
import time

import pytest

pytest.importorskip("ai2thor")

from ai2thor.controller import Controller  # noqa: E402

from cook2ltl.execution.launcher import embedded_executable, start_embedded  # noqa: E402

FRIDGE = "Fridge|-02.10|+00.00|+01.07"
MICROWAVE = "Microwave|-00.24|+01.69|-02.53"


@pytest.fixture(scope="module")
def controller(thor_home):
    c = start_embedded("FloorPlan1")
    yield c
    c.stop()


@pytest.fixture
def kitchen(controller):
    controller.reset("FloorPlan1")
    return controller


def first(event, object_type):
    return next(o for o in event.metadata["objects"] if o["objectType"] == object_type)


def step_ok(controller, action, **args):
    event = controller.step(action=action, **args)
    assert event.metadata["lastActionSuccess"], event.metadata["errorMessage"]
    return event


def test_the_plain_controller_constructor_launches_the_kitchen(thor_home):
    executable = str(embedded_executable())
    c = Controller(local_executable_path=executable, scene="FloorPlan2", x_display=":0", width=64, height=48)
    try:
        event = c.last_event
        assert event.metadata["sceneName"] == "FloorPlan2_physics"
        assert (event.metadata["screenWidth"], event.metadata["screenHeight"]) == (64, 48)
        assert event.metadata["lastAction"] == "Initialize" and event.frame is None
        assert step_ok(c, "Pass").metadata["lastAction"] == "Pass"
    finally:
        player = c.server.unity_proc
        c.stop()
    assert player.poll() is not None  # no kitchen process left behind


def test_the_build_lists_the_thirty_kitchens(kitchen):
    assert kitchen.scenes_in_build == {f"FloorPlan{n}_physics" for n in range(1, 31)}


def test_microwave_the_potato(kitchen):
    potato = first(kitchen.last_event, "Potato")["objectId"]
    step_ok(kitchen, "PickupObject", objectId=potato)
    step_ok(kitchen, "OpenObject", objectId=MICROWAVE)
    step_ok(kitchen, "PutObject", objectId=MICROWAVE)
    step_ok(kitchen, "CloseObject", objectId=MICROWAVE)
    event = step_ok(kitchen, "ToggleObjectOn", objectId=MICROWAVE)
    cooked = event.get_object(potato)
    assert cooked["isCooked"] and cooked["temperature"] == "Hot"
    assert cooked["parentReceptacles"] == [MICROWAVE]


def test_chop_the_tomato(kitchen):
    tomato = first(kitchen.last_event, "Tomato")["objectId"]
    step_ok(kitchen, "PickupObject", objectId=first(kitchen.last_event, "ButterKnife")["objectId"])
    event = step_ok(kitchen, "SliceObject", objectId=tomato)
    assert event.metadata["actionReturn"][0] == f"{tomato}|TomatoSliced_0"
    assert len(event.objects_by_type("TomatoSliced")) == 7 and event.get_object(tomato) is None


def test_cut_the_bread_and_toast_a_slice(kitchen):
    bread = first(kitchen.last_event, "Bread")["objectId"]
    step_ok(kitchen, "PickupObject", objectId=first(kitchen.last_event, "ButterKnife")["objectId"])
    step_ok(kitchen, "SliceObject", objectId=bread)
    step_ok(kitchen, "DropHandObject")
    step_ok(kitchen, "PickupObject", objectId=f"{bread}|BreadSliced_1")
    step_ok(kitchen, "PutObject", objectId=first(kitchen.last_event, "Toaster")["objectId"])
    event = step_ok(kitchen, "ToggleObjectOn", objectId=first(kitchen.last_event, "Toaster")["objectId"])
    assert event.get_object(f"{bread}|BreadSliced_1")["isCooked"]


def test_refrigerate_the_apple(kitchen):
    apple = first(kitchen.last_event, "Apple")["objectId"]
    step_ok(kitchen, "PickupObject", objectId=apple)
    step_ok(kitchen, "OpenObject", objectId=FRIDGE)
    step_ok(kitchen, "PutObject", objectId=FRIDGE)
    event = step_ok(kitchen, "CloseObject", objectId=FRIDGE)
    chilled = event.get_object(apple)
    assert chilled["temperature"] == "Cold" and not chilled["visible"]
    assert apple in event.get_object(FRIDGE)["receptacleObjectIds"]


def test_a_failed_step_says_why_and_changes_nothing(kitchen):
    before = kitchen.last_event.metadata["objects"]
    event = kitchen.step(action="PickupObject", objectId=first(kitchen.last_event, "Egg")["objectId"])
    assert not event.metadata["lastActionSuccess"]
    assert "inside the closed Fridge" in event.metadata["errorMessage"]
    assert event.metadata["objects"] == before


def test_argument_errors_raise_like_thor(kitchen):
    with pytest.raises(ValueError, match="needs an objectId"):
        kitchen.step(action="PickupObject")
    with pytest.raises(ValueError, match="not a kitchen action"):
        kitchen.step(action="Fly")


def test_reset_brings_back_the_starting_kitchen(kitchen):
    step_ok(kitchen, "OpenObject", objectId=FRIDGE)
    event = kitchen.reset("FloorPlan1")
    assert not event.get_object(FRIDGE)["isOpen"]
    assert kitchen.reset("FloorPlan5").metadata["sceneName"] == "FloorPlan5_physics"


def test_a_step_takes_milliseconds(kitchen):
    timings = []
    for _ in range(60):
        start = time.perf_counter()
        kitchen.step(action="Pass")
        timings.append(time.perf_counter() - start)
    median_ms = statistics.median(timings) * 1000
    print(f"median step through the Controller: {median_ms:.2f} ms")
    assert median_ms < 25
