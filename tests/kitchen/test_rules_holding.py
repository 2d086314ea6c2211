"""Picking up, putting down and dropping: THOR's one-object hand and receptacle rules."""

from cook2ltl.simulator import rules
from cook2ltl.simulator.metadata import objects_metadata

FRIDGE = "Fridge|-02.10|+00.00|+01.07"
EGG_IN_FRIDGE = "Egg|-02.04|+00.81|+01.24"
PLATE_IN_CABINET = "Plate|+00.96|+01.65|-02.61"


def meta(bench, object_id):
    return next(o for o in objects_metadata(bench.state) if o["objectId"] == object_id)


def test_pickup_takes_a_visible_pickupable_object(bench):
    apple = bench.id("Apple")
    bench.do("PickupObject", apple)
    assert bench.state.held == apple
    m = meta(bench, apple)
    assert m["isPickedUp"] and m["parentReceptacles"] is None


def test_pickup_refused_while_the_hand_is_full(bench):
    bench.do("PickupObject", "Apple")
    bench.refuse("PickupObject", "Tomato", match="one object at a time")


def test_pickup_refused_for_fixtures(bench):
    bench.refuse("PickupObject", "CounterTop", match="not pickupable")


def test_pickup_refused_inside_a_closed_fridge_until_it_opens(bench):
    bench.refuse("PickupObject", EGG_IN_FRIDGE, match="inside the closed Fridge")
    bench.do("OpenObject", FRIDGE)
    bench.do("PickupObject", EGG_IN_FRIDGE)


def test_force_action_skips_the_reach_check(bench):
    bench.do("PickupObject", EGG_IN_FRIDGE, forceAction=True)


def test_pickup_refused_for_broken_objects(bench):
    bench.do("BreakObject", "Vase")
    bench.refuse("PickupObject", "Vase", match="broken")


def test_missing_and_unknown_object_ids(bench):
    bench.refuse("PickupObject", match="needs an objectId", code="MissingArguments")
    bench.refuse("PickupObject", "Apple|+09.00|+09.00|+09.00", match="No object with objectId")


def test_unknown_action_is_an_invalid_action(bench):
    result = rules.apply(bench.state, {"action": "Teleportation"})
    assert not result.success and result.error_code == "InvalidAction"


def test_put_places_the_held_object_in_a_compatible_receptacle(bench):
    bench.do("PickupObject", "Apple")
    bench.do("PutObject", "Bowl")
    assert bench.state.held is None
    assert bench["Apple"].parent == bench.id("Bowl")
    assert bench.id("Apple") in meta(bench, bench.id("Bowl"))["receptacleObjectIds"]


def test_put_refused_with_an_empty_hand(bench):
    bench.refuse("PutObject", "Bowl", match="holds nothing")


def test_put_refused_onto_a_non_receptacle(bench):
    bench.do("PickupObject", "Apple")
    bench.refuse("PutObject", "Tomato", match="not a receptacle")


def test_put_refused_into_a_closed_receptacle(bench):
    bench.do("PickupObject", "Apple")
    bench.refuse("PutObject", FRIDGE, match="is closed")
    bench.do("OpenObject", FRIDGE)
    bench.do("PutObject", FRIDGE)


def test_put_refused_onto_something_shut_away(bench):
    bench.do("PickupObject", "Apple")
    bench.refuse("PutObject", PLATE_IN_CABINET, match="inside the closed Cabinet")


def test_put_refused_for_incompatible_types(bench):
    bench.hold("Knife")
    bench.refuse("PutObject", "Toaster", match="A Knife cannot be put in or on a Toaster")
    bench.do("PutObject", "CounterTop")


def test_put_refused_into_itself_or_its_own_contents(bench):
    bench.do("PickupObject", "Apple")
    bench.do("PutObject", "Bowl")
    bench.do("PickupObject", "Bowl")
    bench.refuse("PutObject", "Bowl", match="into itself")
    bench.refuse("PutObject", "Apple", match="into itself")


def test_contents_travel_with_their_container(bench):
    bench.do("PickupObject", "Apple")
    bench.do("PutObject", "Bowl")
    bench.do("PickupObject", "Bowl")
    assert meta(bench, bench.id("Apple"))["position"] == meta(bench, bench.id("Bowl"))["position"]
    bench.do("OpenObject", FRIDGE)
    bench.do("PutObject", FRIDGE)
    assert meta(bench, bench.id("Apple"))["parentReceptacles"] == [bench.id("Bowl"), FRIDGE]
    assert bench["Apple"].temperature == "Cold"


def test_drop_puts_the_held_object_on_the_floor(bench):
    bench.do("PickupObject", "Apple")
    bench.do("DropHandObject")
    assert bench.state.held is None
    assert bench["Apple"].parent == bench.id("Floor")


def test_drop_refused_with_an_empty_hand(bench):
    bench.refuse("DropHandObject", match="holds nothing")


def test_held_object_follows_the_agent(bench):
    bench.do("PickupObject", "Apple")
    before = meta(bench, bench.id("Apple"))["position"]
    bench.do("MoveAhead")
    assert meta(bench, bench.id("Apple"))["position"] != before
