"""The executor on hand-written formulas, through ai2thor's Controller driving the embedded kitchen:
atoms to THOR actions, names to objectIds, the trace fed to LTL progression, and failures kept, not repaired."""

import pytest

from cook2ltl.errors import UserError
from cook2ltl.execution.executor import COMPOSED, INTERACTIONS
from cook2ltl.execution.rollout import ActionRefused, RolloutFinished, RolloutLimits, RolloutStarted, Stop, rollout
from cook2ltl.ltl import Atom, Verdict, monitor, parse, to_spot
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.world.thor_facts import PREDICATES
from cook2ltl.world.thor_names import Binding, UnknownObject, resolve

FRIDGE = "Fridge|-02.10|+00.00|+01.07"
TOMATO = "Tomato|-00.39|+01.14|-00.81"
BUTTER_KNIFE = "ButterKnife|-00.41|+01.11|-00.46"  # on the counter; the Knife is in a closed drawer


def roll(kitchen, text, **options):
    events = list(rollout(kitchen, parse(text), **options))
    assert isinstance(events[0], RolloutStarted) and isinstance(events[-1], RolloutFinished)
    return events[-1].rollout, events


def objects(kitchen, object_type):
    return [o for o in kitchen.last_event.metadata["objects"] if o["objectType"] == object_type]


def test_refrigerate_the_apple_step_by_step(kitchen):
    formula = "F(open(fridge) & F(pick_up(apple) & F(put(apple, fridge) & F close(fridge))))"
    result, events = roll(kitchen, formula)
    assert [s.attempt.atom.text for s in result.steps] == [
        "open(fridge)", "pick_up(apple)", "put(apple, fridge)", "close(fridge)"]
    assert [to_spot(s.remaining) for s in result.steps] == [
        'F("pick_up(apple)" & F("put(apple, fridge)" & F"close(fridge)"))',
        'F("put(apple, fridge)" & F"close(fridge)")',
        'F"close(fridge)"',
        "true",
    ]
    assert [s.verdict for s in result.steps][-1] == Verdict.SATISFIED and result.stop == Stop.SATISFIED
    assert [len(s.met) for s in result.steps] == [1, 2, 3, 4]
    assert [type(e).__name__ for e in events] == ["RolloutStarted", *["Stepped"] * 4, "RolloutFinished"]
    # Each primitive: the pose THOR offers, a teleport there, then the interaction itself.
    pick_up = result.steps[1].attempt
    assert [c.action["action"] for c in pick_up.calls] == ["GetInteractablePoses", "TeleportFull", "PickupObject"]
    apple = pick_up.calls[-1].action["objectId"]
    assert apple.startswith("Apple|") and result.binding.objects["apple"] == apple
    assert result.binding.objects["fridge"] == FRIDGE
    (inside,) = [o for o in kitchen.last_event.metadata["objects"] if o["objectId"] == apple]
    assert inside["parentReceptacles"] == [FRIDGE] and inside["temperature"] == "Cold"


def test_the_trace_is_what_ltl_monitor_sees(kitchen):
    formula = parse("F(pick_up(potato) & F(open(microwave) & F(put(potato, microwave) & F(close(microwave) & "
                    "F(turn_on(microwave) & F(wait U (hot(potato) & F turn_off(microwave))))))))")
    result, _ = roll(kitchen, to_spot(formula))
    on = result.steps[4]
    assert on.attempt.atom == Atom("turn_on", ("microwave",)) and on.facts == {Atom("hot", ("potato",))}
    assert len(result.steps) == 6  # the potato is hot at once, so the wait is met without a step of its own
    checked = list(monitor(formula, [s.atoms for s in result.steps]))
    assert [c.remaining for c in checked] == [s.remaining for s in result.steps]
    assert checked[-1].verdict == result.verdict == Verdict.SATISFIED


def test_names_resolve_to_the_scenes_objects(kitchen):
    result, _ = roll(kitchen, "F(pick_up(knife) & F(slice(tomato) & F(put(knife, countertop) & F pick_up(tomato))))")
    assert result.binding.objects["knife"] == BUTTER_KNIFE  # the one in reach beats the one shut in a drawer
    slice_call = result.steps[1].attempt.calls[-1].action
    assert dict(slice_call) == {"action": "SliceObject", "objectId": TOMATO}
    # The name goes on standing for what was cut: picking the tomato up takes a slice.
    held = [o for o in kitchen.last_event.metadata["objects"] if o["isPickedUp"]]
    assert [o["objectType"] for o in held] == ["TomatoSliced"] and held[0]["objectId"].startswith(TOMATO + "|")


def test_a_stove_burner_is_switched_by_its_knob(kitchen):
    result, _ = roll(kitchen, "F(pick_up(pan) & F(put(pan, stove_burner) & F turn_on(stove_burner)))")
    burner = result.binding.objects["stove_burner"]
    toggle = result.steps[2].attempt.calls[-1].action
    assert toggle["action"] == "ToggleObjectOn" and toggle["objectId"].startswith("StoveKnob|")
    (knob,) = [o for o in kitchen.last_event.metadata["objects"] if o["objectId"] == toggle["objectId"]]
    assert knob["controlledObjects"] == [burner]
    assert {o["temperature"] for o in objects(kitchen, "Pan")} == {"Hot"}


def test_a_plan_that_slices_without_a_knife_fails_with_the_kitchens_reason(kitchen):
    result, events = roll(kitchen, "F(slice(tomato) & F pick_up(tomato))")
    assert result.stop == Stop.FAILED and result.steps == () and result.verdict == Verdict.PRESUMABLY_FALSE
    (refused,) = [e.attempt for e in events if isinstance(e, ActionRefused)]
    assert refused.error == "slice(tomato): Slicing needs a ButterKnife or Knife in hand; the agent holds nothing"
    assert refused.calls[-1].action["action"] == "SliceObject" and not refused.calls[-1].success
    assert objects(kitchen, "Tomato") and not objects(kitchen, "TomatoSliced")  # nothing was fixed behind its back


def test_put_needs_the_object_in_hand_and_sends_nothing_otherwise(kitchen):
    result, _ = roll(kitchen, "F(put(apple, fridge))")
    (refused,) = result.failures
    assert refused.error == "put(apple, fridge): the agent holds nothing; the plan must pick up apple first"
    assert refused.calls == ()
    result, _ = roll(kitchen, "F(pick_up(bread) & F put(apple, countertop))")
    assert result.failures[0].error.startswith("put(apple, countertop): the agent holds Bread|")


def test_a_refused_action_is_not_a_step_and_ends_the_rollout(kitchen):
    result, _ = roll(kitchen, "F(pick_up(apple) & F(put(apple, fridge) & F close(fridge)))")
    assert [s.attempt.atom.text for s in result.steps] == ["pick_up(apple)"]
    assert result.failures[0].error == f"put(apple, fridge): {FRIDGE} is closed; open it before putting things in"
    assert to_spot(result.steps[-1].remaining) == 'F("put(apple, fridge)" & F"close(fridge)")'


def test_alternatives_are_tried_in_order(kitchen):
    # The egg is in the closed fridge: its branch is refused, the tomato's is taken.
    result, _ = roll(kitchen, "F pick_up(egg) | F pick_up(tomato)")
    assert [a.atom.text for a in result.failures] == ["pick_up(egg)"]
    assert "inside the closed" in result.failures[0].error
    assert [s.attempt.atom.text for s in result.steps] == ["pick_up(tomato)"] and result.stop == Stop.SATISFIED


def test_a_forbidden_action_is_never_done(kitchen):
    result, _ = roll(kitchen, "F pick_up(apple) & G !open(fridge)")
    assert [s.attempt.atom.text for s in result.steps] == ["pick_up(apple)"]
    assert result.verdict == Verdict.PRESUMABLY_TRUE and result.stop == Stop.SATISFIED
    result, _ = roll(kitchen, "F open(fridge) & G !open(fridge)")
    assert result.steps == () and result.stop == Stop.STUCK
    assert not [o for o in objects(kitchen, "Fridge") if o["isOpen"]]


def test_wait_holds_until_the_condition_or_gives_up(kitchen):
    result, _ = roll(kitchen, "F(turn_on(toaster) & F(wait U hot(potato)))", limits=RolloutLimits(max_waits=2))
    assert [s.attempt.atom.text for s in result.steps] == ["turn_on(toaster)", "wait", "wait"]
    assert result.stop == Stop.WAITED
    assert [c.action["action"] for c in result.steps[1].attempt.calls] == ["Pass"]
    # The kitchen has no clock: one wait stands for any duration.
    result, _ = roll(kitchen, "F(pick_up(apple) & F(wait U elapsed(5_minutes)))")
    assert [s.attempt.atom.text for s in result.steps] == ["pick_up(apple)", "wait"]
    assert result.steps[-1].facts == {Atom("elapsed", ("5_minutes",))} and result.verdict == Verdict.SATISFIED


def test_what_the_kitchen_cannot_report_is_named(kitchen):
    result, events = roll(kitchen, "F(pick_up(egg) & F boiled(egg))")
    assert events[0].unobservable == (Atom("boiled", ("egg",)),)
    assert result.stop == Stop.FAILED  # the egg is in the closed fridge


@pytest.mark.parametrize("formula, error, message", [
    ("F pick_up(oven)", UnknownObject, "No object 'oven' in FloorPlan1."),
    ("F fill(mug, milk)", UnknownObject, "No liquid 'milk' in FloorPlan1."),
    ("F put(apple)", UserError, "put(apple): put takes 2 arguments."),
    ("F(wait(apple) U cold(apple))", UserError, "wait(apple): wait takes 0 arguments."),
])
def test_what_cannot_run_is_a_user_error_before_anything_moves(kitchen, formula, error, message):
    with pytest.raises(error) as raised:
        list(rollout(kitchen, parse(formula)))
    assert raised.value.message == message
    assert kitchen.last_event.metadata["lastAction"] == "Initialize"  # nothing sent since the reset


def test_the_unknown_object_error_lists_the_kitchens_objects(kitchen):
    with pytest.raises(UnknownObject) as raised:
        list(rollout(kitchen, parse("F pick_up(oven)")))
    assert raised.value.hint.startswith("the kitchen has: apple, book, bottle, bowl, bread, butter_knife, cabinet,")
    assert "stove_burner" in raised.value.hint


def test_a_binding_is_immutable_and_grows():
    first = Binding()
    second = first.bind("apple", "Apple|1")
    assert first.objects == {} and second.objects == {"apple": "Apple|1"}
    with pytest.raises(TypeError):
        second.objects["pear"] = "Pear|1"


def test_the_executor_covers_the_ai2thor_primitive_set():
    primitives = load_primitives("ai2thor")
    assert sorted(p.name for p in primitives.primitives) == sorted([*INTERACTIONS, *COMPOSED])
    assert set(primitives.states) <= set(PREDICATES)  # every state a wait may wait for can be observed


def test_a_cut_object_thor_keeps_beside_its_pieces_is_not_chosen():
    objects = [
        {"objectId": "Tomato|1", "objectType": "Tomato", "isSliced": True, "distance": 0.5},
        {"objectId": "Tomato|1|TomatoSliced_0", "objectType": "TomatoSliced", "distance": 0.9},
    ]
    chosen, binding = resolve("tomato", objects, Binding().bind("tomato", "Tomato|1"))
    assert chosen == "Tomato|1|TomatoSliced_0" and binding.objects == {"tomato": "Tomato|1"}
