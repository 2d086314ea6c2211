"""Primitive sets as data, and the ProgPrompt prompt built from them."""

import pytest

from cook2ltl import paths
from cook2ltl.domain.actions import Action
from cook2ltl.errors import UserError
from cook2ltl.reduce.action import parameter
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.prompt import build_prompt, example_functions, header

PAPER_RECIPE = ["stir", "cut", "pour", "turn", "shake", "pick_up", "put", "remove", "open", "close", "turn_on",
                "turn_off", "taste", "wait"]
PAPER_AI2THOR = ["pick_up", "put", "drop", "open", "close", "break", "cook", "slice", "turn_on", "turn_off", "use",
                 "fill", "empty", "wait"]


def action(verb, *params):
    return Action(verb, tuple(parameter(category, text) for category, text in params))


def test_the_papers_two_sets_with_their_parameters():
    recipe, thor = load_primitives("recipe"), load_primitives("ai2thor")
    assert [p.name for p in recipe.primitives] == PAPER_RECIPE
    assert [p.name for p in thor.primitives] == PAPER_AI2THOR
    assert recipe.get("put").params == ("what", "where")
    assert recipe.get("wait").params == ("condition",) and recipe.get("wait").object_arity == 0
    assert thor.get("fill").params == ("what", "liquid")
    assert {"stovetop", "oven", "pot"} <= set(recipe.objects)
    assert {"fridge", "microwave", "knife", "stove_burner"} <= set(thor.objects)


def test_a_lab_adds_its_own_set_without_code(tmp_path):
    (tmp_path / "arm.txt").write_text("def serve(soup: what):\n    grasp(bowl)\n    place(bowl, table)\n")
    (tmp_path / "arm.toml").write_text(
        'name = "arm"\nexamples = "arm.txt"\nobjects = ["bowl", "table"]\n'
        '[primitives]\ngrasp = ["what"]\nplace = ["what", "where"]\n')
    arm = load_primitives(str(tmp_path / "arm.toml"))
    assert arm.name == "arm" and [p.name for p in arm.primitives] == ["grasp", "place"]
    prompt = build_prompt(arm, [], action("serve", ("what", "the soup")), comments=False)
    assert prompt.text.startswith("from actions import grasp, place\nobjects = [bowl, table]\n")


@pytest.mark.parametrize("content, problem", [
    ("name = 'x'\nexamples = 'e.txt'\nobjects = ['pot']\n", "primitives is missing"),
    ("examples = 'e.txt'\nobjects = ['pot']\n[primitives]\n'pick up' = ['what']\n", "has the key 'pick up', which must be a lower-case identifier"),
    ("examples = 'e.txt'\n[primitives]\nput = ['what']\n", "`objects` is empty"),
    ("examples = 'e.txt'\nobjects = ['pot']\nstates = ['open']\n[primitives]\nopen = ['what']\n", "both a primitive and a state"),
    ("objects = ['pot']\n[primitives]\nput = ['what']\n", "examples is missing: it must be the file of the prompt's example"),
    ("examples = 'missing.txt'\nobjects = ['pot']\n[primitives]\nput = ['what']\n", "No examples file at"),
    ("this is = = not toml", "not valid TOML"),
    ("examples = 'e.txt'\nobjects = ['pot']\n[primitives]\nput = ['what']\n[thor]\ngrasp = 'pick_up'\n",
     "[thor] names grasp, which the set's [primitives] do not have"),
])
def test_a_broken_set_is_a_user_error_with_a_hint(tmp_path, content, problem):
    (tmp_path / "e.txt").write_text("def f(x: what):\n    put(x)\n")
    (tmp_path / "set.toml").write_text(content)
    with pytest.raises(UserError, match=problem.replace("[", r"\[")) as raised:
        load_primitives(str(tmp_path / "set.toml"))
    assert raised.value.hint


def test_an_unknown_set_names_the_choices():
    with pytest.raises(UserError) as raised:
        load_primitives("kitchen-robot")
    assert "recipe or ai2thor" in raised.value.hint


def test_examples_calling_a_non_primitive_are_refused(tmp_path):
    (tmp_path / "e.txt").write_text("def boil(egg: what):\n    fry(egg)\n")
    (tmp_path / "set.toml").write_text("examples = 'e.txt'\nobjects = ['pot']\n[primitives]\nput = ['what', 'where']\n")
    with pytest.raises(UserError, match=r"fry\(egg\) is not one of the primitives"):
        example_functions(load_primitives(str(tmp_path / "set.toml")))


def test_the_papers_prompt_files_are_fixed():
    for name in ("recipe", "ai2thor"):
        text = (paths.assets_dir() / "prompts" / f"{name}.txt").read_text()
        assert "\t" not in text  # the paper's files mix tabs and spaces
        assert "pick up(" not in text and "turn on(" not in text  # calls are identifiers
    thor = load_primitives("ai2thor")
    store = dict(example_functions(thor))["def store(fruit: what, cabinet: where):"]
    assert "pick_up(fruit)" in store and "put(fruit)" not in store  # the paper wrote put(fruit) for pick up


def test_prompt_order_keeps_the_static_prefix_first():
    recipe = load_primitives("recipe")
    boil = build_prompt(recipe, [], action("boil", ("what", "the eggs")), comments=False)
    chop = build_prompt(recipe, ["boil"], action("chop", ("what", "an onion")), comments=False)
    assert boil.static == chop.static  # what llama.cpp keeps in its KV cache
    assert boil.text.startswith(f"from actions import {', '.join(PAPER_RECIPE)}\nobjects = [water, ")
    assert boil.static.index("def cook(pasta: what):") < boil.static.index("def bake(cake: what, oven: where, 30_minutes: time):")
    assert boil.dynamic == "objects += [eggs]\n\ndef boil(eggs: what):\n"
    assert chop.dynamic == "from library import boil\nobjects += [onion]\n\ndef chop(onion: what):\n"
    assert boil.digest != chop.digest


def test_the_examples_keep_or_drop_their_comments():
    recipe = load_primitives("recipe")
    with_comments = build_prompt(recipe, [], action("boil", ("what", "eggs")), comments=True).static
    without = build_prompt(recipe, [], action("boil", ("what", "eggs")), comments=False).static
    assert "    # wait until the water boils\n    wait(water == boiled)\n" in with_comments
    assert "#" not in without and "    wait(water == boiled)\n" in without
    assert without.endswith("    turn_off(oven)\n\n")  # a blank line closes every function


def test_header_follows_the_papers_notation():
    bake = action("bake", ("what", "the cake"), ("where", "a hot oven"), ("time", "30 minutes"))
    assert header(bake) == "def bake(cake: what, hot_oven: where, 30_minutes: time):\n"
    cool = action("refrigerate", ("what", "the cookie"), ("time", "until cold"))
    assert header(cool) == "def refrigerate(cookie: what, until_cold: time):\n"
    assert [p.value for p in cool.parameters] == ["cookie", "cold"]  # the state a wait reaches
