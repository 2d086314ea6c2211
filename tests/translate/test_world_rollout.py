"""A translated recipe rolled out in the world model: one state from step to step, the formula progressed after
every line, problems reported by step (translations made with the fake parsers and a scripted model)."""

from __future__ import annotations

import json
import threading
from dataclasses import replace

import pytest

from cook2ltl.domain.actions import Call
from cook2ltl.errors import UserError
from cook2ltl.ltl.ast import TRUE, Atom
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline.records import Variant
from cook2ltl.pipeline.translator import Translator, translate
from cook2ltl.pipeline.world_rollout import (
    ActionRolled,
    Began,
    RecipeRolledOut,
    StepRolled,
    recipe_rollout_json,
    roll_out_recipe,
)
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.world.kitchens import grounding
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel

PRIMITIVES = load_primitives("recipe")
PASTA = "Cook the pasta. Drain the pasta."
SPANS = {
    "Cook the pasta.": [("VERB", "Cook"), ("WHAT", "the pasta")],
    "Drain the pasta.": [("VERB", "Drain"), ("WHAT", "the pasta")],
    "Put the egg in the fridge.": [("VERB", "Put"), ("WHAT", "the egg"), ("WHERE", "the fridge")],
}
ANSWERS = {"cook": "pick_up(pot)\nput(pot, stovetop)\npick_up(pasta)\nput(pasta, pot)\nturn_on(stovetop)\n"
                   "wait(pasta == cooked)",
           "drain": "pick_up(pot)\nput(pasta, colander)"}


@pytest.fixture(scope="module")
def kitchen():
    return grounding(PRIMITIVES)


def translated(kitchen, text: str = PASTA):
    translator = Translator(PRIMITIVES, ScriptedModel(dict(ANSWERS)), None, Variant.AR, grounding=kitchen)
    events = translate(parse_recipe(text, ScriptedSpans(SPANS), ScriptedDependencies()), translator)
    return list(events)[-1].translation


def rolled_out(translation, **options):
    events = list(roll_out_recipe(translation, PRIMITIVES, **options))
    return events, next((e.rollout for e in events if isinstance(e, RecipeRolledOut)), None)


def test_step_two_finds_what_step_one_left_and_the_formula_is_satisfied(kitchen):
    translation = translated(kitchen)
    events, rollout = rolled_out(translation)
    assert isinstance(events[0], Began) and (events[0].steps, events[0].actions) == (2, 2)
    assert [type(e) for e in events[1:]] == [ActionRolled, StepRolled, ActionRolled, StepRolled, RecipeRolledOut]
    cook, drain = (step.actions[0] for step in rollout.steps)
    assert [line.call.text() for line in cook.lines][-1] == "wait(pasta == cooked)"
    assert ("cooked", "pasta") in cook.lines[-1].added and Atom("cooked", ("pasta",)) in cook.lines[-1].facts
    # the pot step 1 put on the stovetop is where step 2 picks it up; the pasta is still cooked
    assert ("in", "pot", "stovetop") in drain.lines[0].removed
    assert all(Atom("cooked", ("pasta",)) in line.facts for line in drain.lines)
    assert [line.written_by for line in drain.lines] == ["model", "planner"]
    assert [line.verdict.value for line in drain.lines] == ["presumably_false", "satisfied"]
    assert rollout.remaining is TRUE and rollout.success
    assert all(step.reached and step.verdict.holds and not step.problems for step in rollout.steps)
    assert rollout.state.holds("cooked", "pasta")


def test_the_json_gives_translate_s_check_and_the_trace_per_action(kitchen):
    translation = translated(kitchen)
    _, rollout = rolled_out(translation)
    data = json.loads(json.dumps(recipe_rollout_json(rollout)))
    assert data["verdict"] == "satisfied" and data["success"] is True
    assert [(s["index"], s["text"], s["problems"]) for s in data["steps"]] == [
        (0, "Cook the pasta.", []), (1, "Drain the pasta.", [])]
    drain = data["steps"][1]["actions"][0]
    assert drain["check"] == translation.steps[1].actions[0].check.json()
    assert set(drain["check"]) >= {"applicable", "effect", "effect_reached", "planner_lines", "problems"}
    assert [line["line"] for line in drain["trace"]] == drain["plan"]
    last = drain["trace"][-1]["line"]
    assert last in ("put(pot, colander)", "pour(pot, colander)")  # the planner's shortest
    assert drain["trace"][-1] | {"added": None, "removed": None, "line": ""} == {
        "line": "", "written_by": "planner", "applied": True, "problem": "", "added": None,
        "removed": None, "facts": ["cooked(pasta)"], "verdict": "satisfied"}
    assert (drain["remaining"], drain["verdict"]) == ("true", "satisfied")
    assert data["steps"][0]["actions"][0]["remaining"] == f'F("pick_up(pot)" & F"{last}")'


def test_a_line_the_world_refuses_is_reported_on_its_step_and_the_state_stays(kitchen):
    translation = translated(kitchen)
    drain = translation.steps[1].actions[0]
    edited = replace(drain, plan=(Call("pick_up", ("oven",)), *drain.plan))
    translation = replace(translation, steps=(translation.steps[0],
                                              replace(translation.steps[1], actions=(edited,))))
    _, rollout = rolled_out(translation)
    cook, drain = rollout.steps
    refused = drain.actions[0].lines[0]
    assert not refused.applied and refused.added == () and "oven" in refused.problem
    assert refused.written_by == ""  # the plan is no longer the one checked: who wrote it is not known
    assert not cook.problems
    assert drain.problems == (f"drain(pasta): line 1 pick_up(oven): {refused.problem}",)
    assert drain.actions[0].lines[-1].applied and rollout.verdict.holds  # the rest of the plan still ran


def test_a_line_translate_dropped_and_the_planner_s_completion_are_reported(kitchen):
    """`put(egg, fridge)` as the recipe says cannot run (nothing holds the egg, the fridge is shut): translate
    dropped it and the planner wrote the plan; the step reports the refusal, the rollout runs the plan."""
    translation = translated(kitchen, "Put the egg in the fridge.")
    _, rollout = rolled_out(translation)
    (step,) = rollout.steps
    (run,) = step.actions
    assert step.problems[0].startswith("put(egg, fridge): line 1 put(egg, fridge): ")
    assert {line.written_by for line in run.lines} == {"planner"} and all(line.applied for line in run.lines)
    assert run.reached and rollout.state.holds("in", "egg", "fridge")


def test_a_step_whose_plan_misses_its_effect_fails_the_rollout(kitchen):
    translation = translated(kitchen)
    drain = translation.steps[1].actions[0]
    shortened = replace(drain, plan=drain.plan[:1])  # picked up, never put in the colander
    translation = replace(translation, steps=(translation.steps[0],
                                              replace(translation.steps[1], actions=(shortened,))))
    _, rollout = rolled_out(translation)
    step = rollout.steps[1]
    assert not step.reached and not rollout.success
    assert "drain(pasta): does not reach in(pasta, colander) here" in step.problems
    assert any(problem.startswith("the step's formula is presumably false") for problem in step.problems)


def test_cancel_stops_between_actions_and_a_translation_without_world_is_refused(kitchen):
    translation = translated(kitchen)
    cancel = threading.Event()
    stream = roll_out_recipe(translation, PRIMITIVES, cancel=cancel)
    assert isinstance(next(stream), Began) and isinstance(next(stream), ActionRolled)
    cancel.set()
    assert [type(e) for e in stream] == [StepRolled]  # the step under way is closed, nothing more is run
    with pytest.raises(UserError, match="needs the world model"):
        list(roll_out_recipe(replace(translation, world_start=None), PRIMITIVES))


def test_a_negated_action_is_not_run_and_a_violated_formula_is_reported_on_its_step(kitchen):
    from cook2ltl.ltl import parse

    text = "Cook the pasta and do not stir the pasta."
    spans = {text: [("VERB", "Cook"), ("WHAT", "the pasta"), ("VERB", "stir"), ("WHAT", "the pasta")]}
    arcs = {text: {"not": ("neg", "stir"), "stir": ("conj", "Cook"), "and": ("cc", "Cook")}}
    translator = Translator(PRIMITIVES, ScriptedModel(dict(ANSWERS)), None, Variant.AR, grounding=kitchen)
    translation = list(translate(parse_recipe(text, ScriptedSpans(spans), ScriptedDependencies(arcs)),
                                 translator))[-1].translation
    _, rollout = rolled_out(translation)
    cook, stir = rollout.steps[0].actions
    assert stir.avoided and stir.lines == () and stir.reached
    assert rollout.verdict.holds and not rollout.steps[0].problems
    _, never = rolled_out(replace(translation, formula=parse('G !"pick_up(pot)"')))
    assert never.verdict.value == "violated" and not never.success
    assert "the recipe's formula is violated at cook(pasta): pick_up(pot)" in never.steps[0].problems


def test_an_action_with_neither_plan_nor_effect_is_not_reached(kitchen):
    """As for `cook(penne)` in a THOR kitchen that has no penne: nothing to do, nothing to observe."""
    translation = translated(kitchen)
    drain = translation.steps[1].actions[0]
    empty = replace(drain, plan=(), check=replace(drain.check, effect=(), plan=(), written_by=()))
    translation = replace(translation, steps=(translation.steps[0], replace(translation.steps[1], actions=(empty,))))
    _, rollout = rolled_out(translation)
    assert not rollout.steps[1].actions[0].reached and not rollout.success
