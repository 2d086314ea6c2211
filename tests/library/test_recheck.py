"""An edited body re-run in the real embedded kitchen with the values of the action it was learnt from."""

import pytest

from cook2ltl.execution.kitchen_check import KitchenValidator
from cook2ltl.library import Library
from cook2ltl.library.recheck import NO_EXAMPLE, Recheck, example_action, live_verbs, recheck
from cook2ltl.reduce.primitives import load_primitives


@pytest.fixture
def library(tmp_path):
    opened = Library(tmp_path / "library.sqlite")
    yield opened
    opened.close()


@pytest.fixture(scope="module")
def kitchen():
    with KitchenValidator(load_primitives("recipe")) as validator:
        yield validator


def test_the_example_action_has_every_parameter_in_signature_order(library):
    entry = library.add("recipe", "mix", ("what", "what", "where"), "put($what, $where)", "qwen", "h",
                        example={"$where": "bowl", "$what2": "sugar", "$what": "flour"})
    action = example_action(entry)
    assert action.text() == "mix(flour, sugar, bowl)" and action.signature == ("what", "what", "where")
    partial = library.add("recipe", "fold", ("what", "where"), "put($what, $where)", "qwen", "h",
                          example={"$what": "flour"})
    assert example_action(partial) is None


def test_library_verbs_in_the_body_are_expanded_before_the_kitchen_runs_it(library, kitchen):
    library.add("recipe", "fetch", ("what",), "open(fridge)\npick_up($what)", "qwen", "h", example={"$what": "egg"})
    boil = library.add("recipe", "boil", ("what",), "put($what, pot)", "qwen", "h", example={"$what": "egg"})
    primitives = load_primitives("recipe")
    verbs = live_verbs(library, "recipe")
    heated = "pick_up(pot)\nput(pot, stovetop)\nfetch($what)\nput($what, pot)\nturn_on(stovetop)\nwait($what == boiled)"
    passed = recheck(boil, heated, primitives, verbs, kitchen)
    assert (passed.validation, passed.problems) == ("passed", ())
    failed = recheck(boil, "put($what, pot)", primitives, verbs, kitchen)
    assert failed.validation == "failed" and failed.problems[0].startswith("line 1 put(egg, pot)")


def test_an_entry_without_example_values_is_left_unchecked(library, kitchen):
    entry = library.add("recipe", "boil", ("what",), "put($what, pot)", "qwen", "h")
    assert recheck(entry, "stir($what)", load_primitives("recipe"), (), kitchen) == Recheck("unchecked", (NO_EXAMPLE,))
