"""Formulas of plans and steps: sequence, and, or, not, until; atoms checked against the primitives."""

from cook2ltl.domain.actions import Action, Call
from cook2ltl.domain.recipe import Connective
from cook2ltl.formulas.formula import (
    Part,
    check,
    direct_calls,
    direct_element,
    plan_element,
    step_element,
)
from cook2ltl.ltl import parse
from cook2ltl.ltl.ast import Atom
from cook2ltl.ltl.patterns import sequenced_visit
from cook2ltl.ltl.progress import holds
from cook2ltl.reduce.action import parameter
from cook2ltl.reduce.primitives import load_primitives

RECIPE = load_primitives("recipe")
a, b, c = Atom("a"), Atom("b"), Atom("c")


def action(verb, *params):
    return Action(verb, tuple(parameter(category, text) for category, text in params))


def step(parts, links):
    return sequenced_visit(step_element(parts, links))


def test_sequence_of_actions():
    assert step([Part(a), Part(b), Part(c)], (Connective.AND, Connective.AND)) is parse("F(a & F(b & F c))")


def test_or_between_actions_is_an_alternative():
    formula = step([Part(a), Part(b), Part(c)], (Connective.OR, Connective.AND))
    assert formula is parse("F(a & F c) | F(b & F c)")


def test_and_between_objects_visits_all_in_any_order():
    put = action("put", ("what", "milk"), ("what", "salt"), ("where", "a saucepan"))
    calls = direct_calls(put, RECIPE.get("put"))
    assert [call.text() for call in calls] == ["put(milk, saucepan)", "put(salt, saucepan)"]
    formula = sequenced_visit(direct_element(put, calls, RECIPE), Atom("stir", ("saucepan",)))
    assert formula is parse('F("put(milk, saucepan)" & F "stir(saucepan)") & F("put(salt, saucepan)" & F "stir(saucepan)")')


def test_not_avoids_the_action_until_the_next_one():
    formula = step([Part(a), Part(b, negated=True), Part(c)], (Connective.AND, Connective.AND))
    assert formula is parse("F(a & (!b U c))")
    assert step([Part(a), Part(b, negated=True)], (Connective.AND,)) is parse("F(a & G !b)")


def test_a_negated_plan_is_avoided_as_a_whole():
    plan = plan_element((Call("put", ("pot", "stovetop")), Call("turn_on", ("stovetop",))), RECIPE)
    formula = step([Part(plan, negated=True)], ())
    assert formula is parse('G !F("put(pot, stovetop)" & F "turn_on(stovetop)")')


def test_wait_is_an_until_inside_the_sequence():
    plan = plan_element((Call("turn_on", ("stovetop",)), Call("wait", ("water", "boiled")),
                         Call("put", ("pasta", "pot")), Call("wait", ("timer", "10_minutes"))), RECIPE)
    formula = sequenced_visit(plan)
    assert formula is parse('F("turn_on(stovetop)" & F(wait U ("boiled(water)" & F("put(pasta, pot)" '
                            '& F(wait U "elapsed(10_minutes)")))))')
    trace = [{"turn_on(stovetop)"}, {"wait"}, {"wait", "boiled(water)"}, {"put(pasta, pot)"}, {"wait"},
             {"elapsed(10_minutes)"}]
    assert holds(formula, [frozenset(parse(x) for x in s) for s in trace])


def test_a_primitive_held_until_its_time():
    stir = action("stir", ("what", "the soup"), ("time", "until thick"))
    calls = direct_calls(stir, RECIPE.get("stir"))
    assert sequenced_visit(direct_element(stir, calls, RECIPE)) is parse('F("stir(soup)" U "thick(soup)")')
    simmer = action("stir", ("what", "sauce"), ("time", "for 5 minutes"))
    element = direct_element(simmer, direct_calls(simmer, RECIPE.get("stir")), RECIPE)
    assert sequenced_visit(element) is parse('F("stir(sauce)" U "elapsed(5_minutes)")')
    stir_then = action("stir", ("what", "sauce"), ("time", "then"))
    assert direct_element(stir_then, direct_calls(stir_then, RECIPE.get("stir")), RECIPE) is Atom("stir", ("sauce",))


def test_objects_that_do_not_fill_the_primitive_need_a_reduction():
    assert direct_calls(action("put", ("what", "the seltzer")), RECIPE.get("put")) is None  # put it where?
    assert direct_calls(action("wait", ("time", "until cool")), RECIPE.get("wait")) is None


def test_atoms_are_checked_against_the_primitive_set():
    good = sequenced_visit(plan_element((Call("stir", ("soup",)), Call("wait", ("soup", "thick"))), RECIPE))
    assert check(good, RECIPE, {"thick": 1}) == ()
    bad = sequenced_visit(plan_element((Call("fry", ("egg",)), Call("put", ("egg",))), RECIPE))
    messages = [problem.message for problem in check(bad, RECIPE, {})]
    assert any("unknown action 'fry'" in m for m in messages)
    assert any("'put' takes 2 arguments, got 1" in m for m in messages)
