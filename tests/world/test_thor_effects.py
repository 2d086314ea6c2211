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


def test_a_recipes_names_find_stand_ins_in_its_kitchen():
    """An ingredient THOR lacks is a food object, a mixture things go into a container, and a word the recipe
    uses for a THOR object (refrigerator) has it before the primitive set's own word (fridge)."""
    from cook2ltl.world.kitchens import grounding

    kitchen = grounding(PRIMITIVES)
    start = kitchen.start(["penne", "cheese", "mix", "refrigerator", "large_bowl", "small_bowl"], {"mix"})
    bound = {name: start.binding[name].split("|")[0] for name in ("penne", "cheese", "mix", "refrigerator")}
    assert bound["refrigerator"] == "Fridge" and "fridge" not in start.state.objects
    assert bound["mix"] in ("Bowl", "Pot", "Pan", "Plate", "Cup", "Mug")
    assert {bound["penne"], bound["cheese"]} <= {"Potato", "Apple", "Tomato", "Egg", "Lettuce", "Bread"}
    assert {"large_bowl", "small_bowl"} <= set(start.state.objects)  # one bowl, and another container
    assert start.scene and len(set(start.binding.values())) == len(start.binding)  # two names never share
    action = act("melt", what="cheese", where="mix")
    assert set(intended_effect(action, kitchen.world, start.state)) == {("hot", "cheese")}


def test_a_stand_in_can_take_the_states_the_recipe_asks_of_it():
    """Fried chicken must be able to be cooked, so it is not the Apple (its pieces never cook) that a name
    gets first; the first fried, then the chopped, as the table's effects say."""
    from cook2ltl.world.effects import cast
    from cook2ltl.world.kitchens import grounding

    kitchen = grounding(PRIMITIVES)
    recipe = [act("chop", what="celery"), act("fry", what="chicken", where="pan")]
    names, places, asks = cast(recipe, kitchen.world)
    assert names == ["celery", "chicken", "pan"] and places == {"pan"}
    assert asks == {"celery": {"sliced"}, "chicken": {"cooked"}}
    start = kitchen.start(names, places, asks)
    fried = start.binding["chicken"].split("|")[0]
    assert fried in ("Potato", "Egg", "Bread") and start.binding["celery"].split("|")[0] != fried
    effect = intended_effect(recipe[1], kitchen.world, start.state)
    assert effect == (("cooked", "chicken"),) and kitchen.planner.plan(kitchen.world, start.state, effect)


def test_an_effect_no_action_could_reach_is_left_out():
    """Food holds nothing in THOR: cheese on the penne cannot be, so spreading has no effect there; in a bowl
    it can."""
    from cook2ltl.world.kitchens import grounding

    kitchen = grounding(PRIMITIVES)
    state = kitchen.start(["penne", "cheese", "bowl"]).state
    assert not kitchen.world.possible(state, ("in", "cheese", "penne"))
    assert kitchen.world.possible(state, ("in", "cheese", "bowl"))
    assert intended_effect(act("spread", what="cheese", where="penne"), kitchen.world, state) == ()
    assert intended_effect(act("put", what="cheese", where="bowl"), kitchen.world, state) == (("in", "cheese", "bowl"),)
