"""A library body checked line by line against the primitive set, as `library edit` and the app's editor do."""

import pytest

from cook2ltl.library.body_check import body_problems
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.reduction import LibraryVerb

SEASON = LibraryVerb("season", ("what",), "pick_up(salt)\nshake(salt)\nstir($what)")


@pytest.fixture(scope="module")
def recipe():
    return load_primitives("recipe")


def check(recipe, body, verb="boil", signature=("what",), verbs=(SEASON,)):
    return body_problems(body, verb, signature, recipe, verbs)


def test_a_body_of_primitives_library_verbs_waits_and_comments_passes(recipe):
    body = "# into the pot\npick_up($what)\n\nput($what, pot)\nseason($what)\nwait($what == boiled)"
    assert check(recipe, body) == []
    assert check(recipe, "remove($what, $where)\nwait(timer == 30_minutes)", "drain", ("what", "where")) == []


@pytest.mark.parametrize("body", ["", "   \n\n", "# only a comment"])
def test_an_empty_body_is_a_problem(recipe, body):
    assert check(recipe, body) == ["the body has no lines"]


def test_each_bad_line_is_named_by_its_number(recipe):
    body = "pick_up($what)\nput($what)\nfly($what)\nput $what in pot\nstir($where)\nremove(pot)"
    assert check(recipe, body) == [
        "line 2: put takes 2 arguments, not 1",
        "line 3: fly with 1 argument(s) is neither a primitive of recipe nor a live library verb",
        "line 4: “put $what in pot” is not a call such as put($what, pot)",
        "line 5: $where is not a parameter of this action (it has $what)",
        "line 6: remove takes 2 arguments, not 1",
    ]


def test_placeholders_must_be_the_actions_parameters(recipe):
    assert check(recipe, "put($what2, $where)", "mix", ("what",)) == [
        "line 1: $what2, $where are not parameters of this action (it has $what)"]
    assert check(recipe, "put($what2, $where)", "mix", ("what", "what", "where")) == []
    assert check(recipe, "stir($what)", "mix", ()) == [
        "line 1: $what is not a parameter of this action (it has none)"]


def test_a_library_verb_needs_its_own_number_of_arguments(recipe):
    assert check(recipe, "season($what, pot)") == [
        "line 1: season with 2 argument(s) is neither a primitive of recipe nor a live library verb"]


def test_a_verb_calling_itself_or_going_round_in_a_cycle_is_refused(recipe):
    assert check(recipe, "boil($what)") == [
        "line 1: boil with 1 argument(s) is neither a primitive of recipe nor a live library verb"]
    simmer = LibraryVerb("simmer", ("what",), "boil($what)")
    assert check(recipe, "simmer($what)", verbs=(simmer,)) == [
        "the body does not expand to primitives (library verbs calling each other in a cycle, or a plan of more "
        "than 60 calls)"]


def test_an_edit_may_replace_the_entry_s_own_old_body(recipe):
    """The entry's current body is in the live verbs; the new one is checked without it."""
    old = LibraryVerb("boil", ("what",), "put($what, pot)")
    assert check(recipe, "pick_up($what)\nput($what, saucepan)", verbs=(old, SEASON)) == []


def test_a_plan_too_long_is_refused(recipe):
    twice = LibraryVerb("twice", ("what",), "stir($what)\n" * 40)
    assert check(recipe, "twice($what)\ntwice($what)", verbs=(twice,))[0].startswith("the body does not expand")
    assert check(recipe, "twice($what)", verbs=(twice,)) == []


def test_the_ai2thor_set_has_its_own_primitives(recipe):
    ai2thor = load_primitives("ai2thor")
    assert body_problems("slice($what)", "cut", ("what",), ai2thor, ()) == []
    assert body_problems("cut($what)", "chop", ("what",), ai2thor, ()) == [
        "line 1: cut with 1 argument(s) is neither a primitive of ai2thor nor a live library verb"]
