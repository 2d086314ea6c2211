"""Frames as actions, plan lines as text, and bodies made parametric for the library."""

import pytest

from cook2ltl.domain.actions import Action, Call
from cook2ltl.domain.recipe import Argument, Connective, Frame, Label, Span
from cook2ltl.reduce.action import actions_of, parameter
from cook2ltl.reduce.body import bind, instantiate, loops, parametrize, placeholders, read_body, without_loops
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.reduction import LibraryVerb, expand

RECIPE = load_primitives("recipe")


def span(label, text):
    return Span(Label(label), 0, len(text), text)


def action(verb, *params):
    return Action(verb, tuple(parameter(category, text) for category, text in params))


@pytest.mark.parametrize("category, text, name, value", [
    ("what", "the penne", "penne", "penne"),
    ("what", "2 large eggs", "large_eggs", "large_eggs"),
    ("where", "a medium saucepan", "medium_saucepan", "medium_saucepan"),
    ("where", "in a saucepan", "saucepan", "saucepan"),
    ("how", "into small pieces", "small_pieces", "small_pieces"),
    ("how", "375 F", "375_f", "375_f"),
    ("time", "until cold", "until_cold", "cold"),
    ("time", "30 minutes", "30_minutes", "30_minutes"),
    ("time", "for 5 minutes", "for_5_minutes", "5_minutes"),
    ("temperature", "medium heat", "medium_heat", "medium_heat"),
    ("time", "20 minutes or until golden", "20_minutes_or_until_golden", "20_minutes"),
    ("time", "for 5 minutes before serving", "for_5_minutes_before_serving", "5_minutes"),
    ("what", "the cook's knife", "cook_knife", "cook_knife"),
])
def test_arguments_become_identifiers(category, text, name, value):
    p = parameter(category, text)
    assert (p.name, p.value) == (name, value)


def test_objects_joined_by_or_are_alternative_actions():
    add = Frame(verb=span("VERB", "Add"), what=(Argument(span("WHAT", "salt")), Argument(span("WHAT", "pepper"))),
                where=(Argument(span("WHERE", "the pot")),), objects_joined_by=Connective.OR)
    assert [a.text() for a in actions_of(add)] == ["add(salt, pot)", "add(pepper, pot)"]
    both = Frame(verb=span("VERB", "Turn on"), what=add.what, where=add.where)
    assert [a.text() for a in actions_of(both)] == ["turn_on(salt, pepper, pot)"]
    assert actions_of(both)[0].signature == ("what", "what", "where")


def test_read_body_skips_comments_and_reports_what_is_not_a_call():
    calls, unread = read_body("# boil\n  put(water, pot)\n\n  wait(water==boiled)\n  print('hi')\n  go(\n")
    assert calls == (Call("put", ("water", "pot")), Call("wait", ("water", "boiled")))
    assert unread == ("print('hi')", "go(")
    assert calls[1].text() == "wait(water == boiled)"


def test_a_learnt_body_serves_other_objects_and_keeps_its_constants():
    learnt = action("microwave", ("what", "the egg"))
    body = (Call("open", ("microwave",)), Call("put", ("egg", "microwave")), Call("close", ("microwave",)),
            Call("wait", ("egg", "hot")))
    stored = parametrize(body, learnt)
    assert stored == "open(microwave)\nput($what, microwave)\nclose(microwave)\nwait($what == hot)"
    reused = instantiate(stored, placeholders(action("microwave", ("what", "a potato"))))
    assert [c.text() for c in reused] == ["open(microwave)", "put(potato, microwave)", "close(microwave)",
                                          "wait(potato == hot)"]


def test_times_and_repeated_categories_are_parameters_too():
    learnt = action("chill", ("what", "the cookie"), ("what", "the milk"), ("time", "until cold"))
    stored = parametrize((Call("put", ("cookie", "fridge")), Call("put", ("milk", "fridge")),
                          Call("wait", ("milk", "cold"))), learnt)
    assert stored == "put($what, fridge)\nput($what2, fridge)\nwait($what2 == $time)"
    again = instantiate(stored, placeholders(action("chill", ("what", "jelly"), ("what", "cream"), ("time", "until set"))))
    assert [c.text() for c in again] == ["put(jelly, fridge)", "put(cream, fridge)", "wait(cream == set)"]


def test_a_body_that_does_not_fit_is_not_instantiated():
    assert instantiate("put($where, pot)", placeholders(action("boil", ("what", "egg")))) is None
    assert instantiate("put($what, pot)\nnot a call", {"$what": "egg"}) is None


def test_library_verbs_expand_to_primitives():
    verbs = {"boil": LibraryVerb("boil", ("what",), "put($what, pot)\nturn_on(stovetop)\nwait($what == boiled)")}
    def find(verb, arity):
        found = verbs.get(verb)
        return found if found and len(found.signature) == arity else None
    plan = expand((Call("boil", ("egg",)), Call("pick_up", ("egg",))), RECIPE, find)
    assert [c.text() for c in plan] == ["put(egg, pot)", "turn_on(stovetop)", "wait(egg == boiled)", "pick_up(egg)"]
    assert expand((Call("fry", ("egg",)),), RECIPE, find) is None
    verbs["loop"] = LibraryVerb("loop", ("what",), "loop($what)")
    assert expand((Call("loop", ("egg",)),), RECIPE, find) is None  # a cycle ends, unexpanded
    assert bind(("what", "what", "where"), ("a", "b", "c")) == {"$what": "a", "$what2": "b", "$where": "c"}


def test_a_plan_going_round_in_circles_is_cut():
    whisk, stir, wait = Call("whisk", ("x",)), Call("stir", ("x",)), Call("wait", ("x", "smooth"))
    assert without_loops((whisk, stir, whisk, stir, whisk)) == (whisk, stir)
    assert without_loops((whisk, whisk, whisk)) == (whisk,)
    assert without_loops((whisk, stir, wait, stir)) == (whisk, stir, wait, stir)
    assert loops("    stir(x)\n    # again\n    stir(x)\n") and not loops("    stir(x)\n    stir(x")  # unfinished line


def test_library_verbs_multiplying_each_other_are_refused():
    verbs = {name: LibraryVerb(name, ("what",), "\n".join([f"{inner}($what)"] * 8))
             for name, inner in (("a", "b"), ("b", "stir"))}
    plan = expand((Call("a", ("soup",)),), RECIPE, lambda verb, arity: verbs.get(verb))
    assert plan is None  # 64 stirs: more than any real action
    assert len(expand((Call("b", ("soup",)),), RECIPE, lambda verb, arity: verbs.get(verb))) == 8
