"""State-aware decoding where a way to the effect is known: the lines name only what matters, a plan stops at its
first detour, and it takes at most a few lines more than the planner's way."""

from cook2ltl.reduce.grounded import SLACK, reduce_in_world
from cook2ltl.reduce.reduction import ReductionSettings
from tests.reduce.fake_model import ScriptedModel
from tests.world.test_recipe_world import PRIMITIVES, act, kitchen  # noqa: F401 (kitchen: a fixture)


def reduce(kitchen, action, answer, effect):
    model = ScriptedModel({action.verb: answer})
    state = kitchen.start(action.objects).state
    return reduce_in_world(action, PRIMITIVES, model, ReductionSettings(), kitchen, state, effect), model


def test_lines_name_only_what_the_effect_needs_the_kitchens_everyday_things_and_the_actions_own(kitchen):
    reduction, model = reduce(kitchen, act("boil", what="pasta"), "turn_on(toaster)\npick_up(pasta)",
                              (("boiled", "pasta"),))
    offered = model.grammars[0].splitlines()
    assert "pick_up(pasta)" in offered and "turn_on(stovetop)" in offered  # the kit's stovetop heats
    assert not any("toaster" in line or "grill" in line for line in offered)  # neither in the kit nor on the way
    assert [c.text() for c in reduction.body] == ["pick_up(pasta)"]


def test_without_an_effect_every_object_may_be_named(kitchen):
    _, model = reduce(kitchen, act("boil", what="pasta"), "turn_on(toaster)", ())
    assert "turn_on(toaster)" in model.grammars[0].splitlines()


def test_a_plan_ends_at_the_first_line_back_to_where_it_had_been(kitchen):
    answer = "pick_up(pasta)\nput(pasta, pot)\npick_up(pasta)\nput(pasta, pot)\nturn_on(stovetop)"
    reduction, model = reduce(kitchen, act("boil", what="pasta"), answer, (("boiled", "pasta"),))
    # the second pick_up(pasta) takes it back out of the pot: the state after the first line again
    assert [c.text() for c in reduction.body] == ["pick_up(pasta)", "put(pasta, pot)"]
    assert len(model.grammars) == 3  # no line is offered after the detour


def test_a_plan_takes_at_most_a_few_lines_more_than_the_planners_way(kitchen):
    way = kitchen.planner.plan(kitchen.world, kitchen.start(["pasta"]).state, (("boiled", "pasta"),))
    wandering = "\n".join(f"{verb}({thing})" for thing in ("fridge", "oven", "fridge", "oven") for verb in ("open", "close"))
    reduction, _ = reduce(kitchen, act("boil", what="pasta"), wandering.replace("close(oven)", "stir(pot)"),
                          (("boiled", "pasta"),))
    assert 0 < len(reduction.body) <= len(way) + SLACK


def test_the_prompt_lists_no_library_verbs_the_line_grammar_could_not_offer(kitchen):
    _, model = reduce(kitchen, act("boil", what="pasta"), "pick_up(pasta)", (("boiled", "pasta"),))
    assert "from library import" not in model.prompts[0]


def test_without_an_effect_a_line_that_changes_nothing_is_kept_and_a_repeat_ends_the_plan(kitchen):
    reduction, _ = reduce(kitchen, act("serve", what="pasta"), "taste(pasta)\ntaste(pasta)\npick_up(pasta)", ())
    assert [c.text() for c in reduction.body] == ["taste(pasta)", "taste(pasta)"]


def test_lines_that_lead_where_the_effect_cannot_be_reached_give_way_to_the_planners_plan(kitchen):
    from cook2ltl.domain.actions import Call
    from cook2ltl.world.check import check_plan

    start = kitchen.start(["pasta"]).state

    class FromTheStartOnly:  # a kitchen where only the untouched start leads to the effect
        def plan(self, world, state, goal):
            return kitchen.planner.plan(world, state, goal) if state == start else None

    checked = check_plan(kitchen.world, start, [Call("pick_up", ("pasta",))], (("boiled", "pasta"),),
                         FromTheStartOnly())
    assert checked.effect_reached and set(checked.written_by) == {"planner"}
    assert "the effect cannot be reached after pick_up(pasta)" in checked.problems[0]
