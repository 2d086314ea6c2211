"""Intended effects in the AI2-THOR world: liquids are told by the container they fill, and the planner's kit
covers what heats, cooks and switches."""

import pytest

from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.world.effects import intended_effect
from tests.world.test_recipe_world import act

PRIMITIVES = load_primitives("ai2thor")


def start(scene, action):
    from cook2ltl.world.kitchens import grounding

    kitchen = grounding(PRIMITIVES, scene=scene)
    return kitchen, kitchen.start(action.objects).state


def test_a_liquid_in_a_container_is_the_container_filled_with_it():
    action = act("fill", what="mug", how="water")
    kitchen, state = start("FloorPlan21", action)
    assert intended_effect(action, kitchen.world, state) == (("filled-with", "mug", "water"),)


@pytest.mark.parametrize("scene, action, goal", [
    # boiled water: a hot kettle full of water; the kettle is heated on a burner switched by its knob
    ("FloorPlan6", act("boil", what="water", where="kettle"), (("hot", "kettle"), ("filled-with", "kettle", "water"))),
    # toasting cooks bread, which only its slices can be: the knife comes from the kit
    ("FloorPlan5", act("toast", what="bread"), (("cooked", "bread"),)),
    # a burner is switched on with its knob
    ("FloorPlan12", act("turn_on", what="stove_burner"), (("on", "stove_burner"),)),
])
def test_the_planner_reaches_effects_that_need_more_than_the_goals_objects(scene, action, goal):
    kitchen, state = start(scene, action)
    effect = intended_effect(action, kitchen.world, state)
    assert effect == goal
    plan = kitchen.planner.plan(kitchen.world, state, effect)
    assert plan is not None
    for call in plan:
        step = kitchen.world.apply(state, call)
        assert step.applied, (call.text(), step.problem)
        state = step.state
    assert all(fact in state.facts for fact in effect)


def test_washing_a_dirty_mug_asks_for_it_clean_and_the_planner_rinses_it():
    action = act("wash", what="mug")
    kitchen, state = start("FloorPlan7", action)
    assert intended_effect(action, kitchen.world, state) == (("clean", "mug"),)  # a clean mug: nothing to do
    dirty = state.changed({("clean", "mug")}, {("dirty", "mug")})
    plan = kitchen.planner.plan(kitchen.world, dirty, (("clean", "mug"),))
    assert plan and any(call.name == "turn_on" for call in plan)
    for call in plan:
        dirty = kitchen.world.apply(dirty, call).state
    assert ("clean", "mug") in dirty.facts and ("dirty", "mug") not in dirty.facts


def test_an_object_the_kitchen_knows_only_by_its_head_noun_is_that_object():
    from cook2ltl.reduce.action import known_objects

    action = known_objects(act("wash", what="dirty_plate", where="sink_basin"), ("plate", "sink_basin", "mug"))
    assert action.text() == "wash(plate, sink_basin)"
    assert known_objects(act("wash", what="wine_bottle"), ("wine_bottle", "bottle")).text() == "wash(wine_bottle)"
    assert known_objects(act("wash", what="blue_zebra"), ("plate",)).text() == "wash(blue_zebra)"
