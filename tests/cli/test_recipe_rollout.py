"""`cook2ltl rollout RECIPE-FILE`: translated with the fake parsers and a scripted model, then rolled out in the
world model; the display, the JSON, the exit code and the options that do not fit a recipe."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from cook2ltl.errors import UserError
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel
from tests.translate.test_world_rollout import ANSWERS, PASTA, SPANS


@pytest.fixture
def recipe(monkeypatch, tmp_path):
    import cook2ltl.assembly.backends

    monkeypatch.setattr(cook2ltl.assembly.backends, "span_extractor", lambda settings: ScriptedSpans(SPANS))
    monkeypatch.setattr(cook2ltl.assembly.backends, "dependency_parser", lambda: ScriptedDependencies())
    monkeypatch.setattr(cook2ltl.assembly.backends, "load_model", lambda name: ScriptedModel(dict(ANSWERS)))
    monkeypatch.setenv("COOK2LTL_LIBRARY", str(tmp_path / "library.sqlite"))
    monkeypatch.setenv("COOK2LTL_CONFIG", str(tmp_path / "none.toml"))
    path = tmp_path / "pasta.txt"
    path.write_text(PASTA)
    return path


def rollout(*arguments: str):
    from cook2ltl.cli import app

    return CliRunner().invoke(app, ["rollout", *arguments], env={"COLUMNS": "160"})


def test_each_line_with_its_writer_and_the_formula_s_progress(recipe):
    shown = rollout(str(recipe))
    assert shown.exit_code == 0, shown.output
    lines = shown.output.splitlines()
    assert lines[0].startswith("pasta.txt · recipe primitives · 2 steps, 2 actions")
    assert "  2. Drain the pasta." in lines
    drain = next(i for i, line in enumerate(lines) if "→ drain(pasta)" in line)
    assert "effect in(pasta, colander) ✓" in lines[drain]
    assert lines[drain + 1].split()[:3] == ["✓", "pick_up(pot)", "model"]
    assert "−in(pot, stovetop)" in lines[drain + 1]  # where step 1 left it
    assert lines[drain + 2].split()[:4] == ["✓", "pour(pot,", "colander)", "planner"]
    assert lines[drain + 3].split() == ["satisfied", "remaining", "⊤"]
    assert lines[-2].startswith("verdict satisfied") and lines[-1] == "success · 2 of 2 steps reached their effects"


def test_json_gives_per_step_the_actions_with_their_check_and_trace(recipe):
    shown = rollout(str(recipe), "--json")
    assert shown.exit_code == 0, shown.output
    data = json.loads(shown.stdout)
    assert data["verdict"] == "satisfied" and data["success"] is True
    step = data["steps"][1]
    assert step["text"] == "Drain the pasta." and step["problems"] == []
    (action,) = step["actions"]
    assert action["action"] == "drain(pasta)" and action["plan"] == ["pick_up(pot)", "pour(pot, colander)"]
    assert action["check"]["effect"] == ["in(pasta, colander)"] and action["check"]["planner_lines"] == 1
    assert [line["written_by"] for line in action["trace"]] == ["model", "planner"]


def test_a_plan_that_misses_its_effect_exits_1_with_the_problem_under_its_step(recipe, monkeypatch):

    # no planner to complete it: drain's plan stops holding the pot
    monkeypatch.setattr("cook2ltl.world.kitchens.FastDownward", lambda kit: None)
    monkeypatch.setattr("cook2ltl.assembly.backends.load_model",
                        lambda name: ScriptedModel({**ANSWERS, "drain": "pick_up(pot)"}))
    shown = rollout(str(recipe))
    assert shown.exit_code == 1
    problems = shown.output[shown.output.index("problems by step"):]
    assert "2. Drain the pasta." in problems and "drain(pasta): the plan does not reach in(pasta, colander)" in problems
    assert "1. Cook the pasta." not in problems and shown.output.splitlines()[-1].startswith("failure · 1 of 2")


def test_options_that_do_not_fit_a_recipe_are_refused(recipe):
    for arguments, message in (((str(recipe), "--no-ground"), "--no-ground turns it off"),
                               ((str(recipe), "--scene", "FloorPlan2"), "--scene are for kitchen tasks"),
                               (("refrigerate-apple", "--primitives", "recipe"), "--primitives is for a recipe")):
        refused = rollout(*arguments)
        assert isinstance(refused.exception, UserError) and message in refused.exception.message
