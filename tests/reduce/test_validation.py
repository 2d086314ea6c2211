"""The kitchen check of a plan, on real runs: ai2thor's Controller driving the embedded kitchen."""

import time

import pytest

from cook2ltl.domain.actions import Action, Primitive, PrimitiveSet
from cook2ltl.errors import UserError
from cook2ltl.execution.kitchen_check import KitchenValidator, unsupported
from cook2ltl.reduce.action import parameter
from cook2ltl.reduce.body import read_body
from cook2ltl.reduce.primitives import load_primitives
from tests.reduce.kitchen_validators import validators  # noqa: F401  (a fixture)

MICROWAVE = "open(microwave)\npick_up(potato)\nput(potato, microwave)\nclose(microwave)\nturn_on(microwave)\nwait(potato == hot)"


def action(verb, *parameters):
    return Action(verb, tuple(parameter(category, text) for category, text in parameters))


def check(validators, primitives, verb_action, body):
    return validators(primitives).validate(verb_action, read_body(body)[0])


def test_a_good_plan_passes(validators):
    result = check(validators, "ai2thor", action("microwave", ("what", "the potato")), MICROWAVE)
    assert result.passed and result.checked and result.status == "passed"
    assert result.problems == () and result.scene == "FloorPlan1"


def test_put_before_pick_up_names_the_line(validators):
    body = "open(microwave)\nput(potato, microwave)\nclose(microwave)\nturn_on(microwave)"
    result = check(validators, "ai2thor", action("microwave", ("what", "the potato")), body)
    assert not result.passed and result.status == "failed"
    assert [(p.line, p.call) for p in result.problems] == [(2, "put(potato, microwave)"), (0, "microwave(potato)")]
    assert result.messages() == ("line 2 put(potato, microwave): the agent holds nothing; "
                                 "the plan must pick up potato first",
                                 "microwave(potato): goal state not reached: potato is not hot at the end")


def test_put_into_a_closed_fridge(validators):
    body = "pick_up(apple)\nput(apple, fridge)\nclose(fridge)"
    result = check(validators, "ai2thor", action("refrigerate", ("what", "the apple")), body)
    assert result.messages()[0] == "line 2 put(apple, fridge): fridge is closed; open it before putting things in"
    assert "line 3 close(fridge)" in result.messages()[1]  # every refused line, not only the first


def test_slice_without_a_knife(validators):
    result = check(validators, "ai2thor", action("chop", ("what", "the tomato")), "slice(tomato)")
    assert result.messages() == ("line 1 slice(tomato): Slicing needs a ButterKnife or Knife in hand; "
                                 "the agent holds nothing",
                                 "chop(tomato): goal state not reached: tomato is not sliced at the end")
    with_knife = check(validators, "ai2thor", action("chop", ("what", "the tomato")), "pick_up(knife)\nslice(tomato)")
    assert with_knife.passed


def test_an_object_the_kitchen_lacks(validators):
    result = check(validators, "ai2thor", action("rinse", ("what", "the water")), "pick_up(water)")
    assert result.problems[0].line == 1 and "No object 'water'" in result.problems[0].message


def test_a_goal_state_that_never_holds(validators):
    body = "open(microwave)\npick_up(potato)\nput(potato, microwave)\nclose(microwave)\nwait(potato == hot)"
    result = check(validators, "ai2thor", action("microwave", ("what", "the potato")), body)
    assert result.messages()[0] == "line 5 wait(potato == hot): goal state not reached: potato never became hot"
    chill = action("chill", ("what", "the apple"), ("time", "until cold"))
    result = check(validators, "ai2thor", chill, "pick_up(apple)\nput(apple, countertop)")
    assert result.messages() == ("chill(apple, cold): goal state not reached: apple is not cold at the end",)


def test_recipe_plans_run_with_stand_ins(validators):
    cook = ("put(water, pot)\npick_up(pot)\nput(pot, stovetop)\nturn_on(stovetop)\nwait(water == hot)\n"
            "pick_up(penne)\nput(penne, pot)\nwait(penne == cooked)\nturn_off(stovetop)")
    assert check(validators, "recipe", action("cook", ("what", "the penne")), cook).passed
    chop = action("chop", ("what", "the onion"))
    assert check(validators, "recipe", chop, "pick_up(knife)\ncut(onion)").passed
    assert "Slicing needs" in check(validators, "recipe", chop, "cut(onion)").problems[0].message
    bake = "pick_up(cake)\nput(cake, baking_pan)\nopen(oven)\nput(baking_pan, oven)\nclose(oven)\nturn_on(oven)"
    result = check(validators, "recipe", action("bake", ("what", "the cake"), ("where", "oven")), bake)
    assert result.messages() == ("line 4 put(baking_pan, oven): the agent holds nothing; "
                                 "the plan must pick up baking_pan first",
                                 "bake(cake, oven): goal state not reached: cake is not hot at the end")


def test_mise_en_place_but_appliances_stay_shut(validators):
    # The egg starts in FloorPlan1's closed fridge: it is set out, but putting it back needs the fridge opened.
    store = action("store", ("what", "the egg"))
    assert check(validators, "ai2thor", store, "pick_up(egg)\nput(egg, pot)").passed
    assert "fridge is closed" in check(validators, "ai2thor", store, "pick_up(egg)\nput(egg, fridge)").problems[0].message


def test_an_object_nothing_can_stand_for_is_not_checked(validators):
    result = check(validators, "recipe", action("blend", ("what", "the ice")), "put(ice, blender)\nturn_on(blender)")
    assert not result.checked and not result.passed and result.status == "unchecked"
    assert result.messages() == ("blend(ice): not checked: the THOR kitchen has nothing that can stand for blender",)


def test_each_plan_starts_from_a_fresh_kitchen_and_is_fast(validators):
    microwave = action("microwave", ("what", "the potato"))
    check(validators, "ai2thor", microwave, MICROWAVE)
    started = time.perf_counter()
    results = [check(validators, "ai2thor", microwave, MICROWAVE) for _ in range(5)]
    assert all(r.passed for r in results)  # the microwave was closed and the potato out again each time
    assert (time.perf_counter() - started) / 5 < 0.5


def test_the_kitchen_starts_lazily_and_closes(tmp_path, monkeypatch):
    pytest.importorskip("ai2thor")
    monkeypatch.setenv("HOME", str(tmp_path))
    monkeypatch.setenv("COOK2LTL_KITCHEN_CACHE", str(tmp_path / "cache"))
    with KitchenValidator(load_primitives("ai2thor")) as validator:
        assert validator._controller is None
        validator.validate(action("chop", ("what", "the tomato")), read_body("slice(tomato)")[0])
        player = validator._controller.server.unity_proc
    assert validator._controller is None and player.poll() is not None


def test_a_primitive_set_the_kitchen_cannot_run():
    robot = PrimitiveSet("arm", (Primitive("grasp", ("what",)), Primitive("put", ("what", "where"))), (), (), "",
                         load_primitives("recipe").source)
    assert unsupported(robot) == ("grasp",) and unsupported(load_primitives("recipe")) == ()
    with pytest.raises(UserError, match="no action for grasp"):
        KitchenValidator(robot)


def test_a_labs_set_says_in_its_file_what_each_primitive_does_in_the_kitchen(tmp_path):
    """A [thor] table makes a set checkable with no code: each primitive as an AI2-THOR one, touch or pour."""
    (tmp_path / "e.txt").write_text("def f(x: what):\n    grasp(x)\n")
    (tmp_path / "arm.toml").write_text("examples = 'e.txt'\nobjects = ['pot']\n[primitives]\ngrasp = ['what']\n"
                                       "poke = ['what']\nzap = ['what']\n[thor]\ngrasp = 'pick_up'\n"
                                       "poke = 'touch'\nzap = 'teleport'\n")
    assert unsupported(load_primitives(str(tmp_path / "arm.toml"))) == ("zap",)



def test_an_ingredient_things_go_into_is_a_container(validators):
    add = action("add", ("what", "splenda"), ("what", "the mix"))
    assert check(validators, "recipe", add, "pick_up(splenda)\nput(splenda, mix)\nstir(mix)").passed
    assert not check(validators, "recipe", add, "put(splenda, mix)").passed


def test_a_verb_implies_its_goal_state(validators):
    chop = action("chop", ("what", "the tomato"))
    assert check(validators, "ai2thor", chop, "pick_up(tomato)").messages() == (
        "chop(tomato): goal state not reached: tomato is not sliced at the end",)
    assert check(validators, "ai2thor", chop, "pick_up(knife)\nslice(tomato)").passed
    assert check(validators, "ai2thor", action("wash", ("what", "the tomato")), "pick_up(tomato)").passed


def test_a_plan_runs_where_the_recipe_has_got_to(validators):
    """Given the recipe so far, the plan runs after the recipe's earlier lines, on the world's binding: the
    tomato already held can be put down, and nothing is set out for it."""
    from cook2ltl.reduce.validation import RecipeSoFar
    from cook2ltl.world.kitchens import grounding

    start = grounding(load_primitives("ai2thor")).start(["penne", "pot"], {"pot"})
    so_far = RecipeSoFar(start.scene, start.binding, read_body("pick_up(penne)")[0])
    add = action("add", ("what", "penne"), ("where", "pot"))
    validator = validators("ai2thor")
    assert validator.validate(add, read_body("put(penne, pot)")[0], so_far).passed
    alone = validator.validate(add, read_body("put(penne, pot)")[0], RecipeSoFar(start.scene, start.binding))
    assert [p.line for p in alone.problems] == [1]
    assert validator.validate(add, read_body("pick_up(penne)\nput(penne, pot)")[0], so_far).problems[0].line == 1
