"""End to end: a task's instruction planned by Algorithm 1 with the ai2thor primitives (fake parsers, a
scripted model, a real library), then executed through ai2thor's Controller; and the `rollout` command."""

import json
from contextlib import contextmanager

import pytest
from typer.testing import CliRunner

from cook2ltl import paths
from cook2ltl.assembly import planning
from cook2ltl.assembly.planning import TaskPlanner
from cook2ltl.assembly.trial import run_trial
from cook2ltl.cli import app
from cook2ltl.execution import launcher
from cook2ltl.execution.tasks import find_task
from cook2ltl.execution.unavailable import KitchenUnavailable
from cook2ltl.library import Library
from cook2ltl.pipeline.translator import Translator
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.world.thor_names import UnknownObject
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.models_required import require_models
from tests.reduce.fake_model import ScriptedModel

SPANS = {
    "Microwave the potato.": [("VERB", "Microwave"), ("WHAT", "the potato")],
    "Refrigerate the apple.": [("VERB", "Refrigerate"), ("WHAT", "the apple")],
}
MICROWAVE = "pick_up(potato)\nopen(microwave)\nput(potato, microwave)\nclose(microwave)\nturn_on(microwave)\n" \
            "wait(potato == hot)\nturn_off(microwave)"
# What the default model wrote for it once: no turn_on, so the potato stays raw.
MICROWAVE_UNPLUGGED = "open(microwave)\npick_up(potato)\nput(potato, microwave)\nclose(microwave)"
runner = CliRunner()
MODEL_CACHE = paths.model_cache_dir()  # read before the module's fixtures move HOME


def stopped(controller) -> bool:
    return controller.server is None or controller.server.unity_proc.poll() is not None


@pytest.fixture
def library(tmp_path):
    opened = Library(tmp_path / "library.sqlite")
    yield opened
    opened.close()


def planner(answers, library, ground=True):
    model = ScriptedModel(answers)
    translator = Translator(load_primitives("ai2thor"), model, library)
    return TaskPlanner(translator, ScriptedSpans(SPANS), ScriptedDependencies(), ground), model


def planned_trial(kitchen, planner, task):
    plan = planner.plan(task.instruction, task.scene)
    events = list(run_trial(kitchen, plan.formula, task.scene, task, plan))
    return events[-1].trial


def test_microwave_the_potato_planned_and_executed(kitchen, library):
    task = find_task("microwave the potato")
    plans, model = planner({"microwave": MICROWAVE}, library)
    done = planned_trial(kitchen, plans, task)
    # The wait is never offered: in THOR the potato is hot as soon as the microwave runs.
    assert [c.text() for c in done.plan.calls] == [line for line in MICROWAVE.splitlines() if "wait" not in line]
    assert done.plan.sources == ("llm",) and model.calls == 1
    assert done.success and done.goal.met and done.rollout.verdict.value == "satisfied"
    # Run it again: the library serves the plan, the model is not asked.
    again = planned_trial(kitchen, plans, task)
    assert again.plan.sources == ("library",) and model.calls == 1 and again.success


def test_a_plan_that_never_turns_the_microwave_on_satisfies_its_formula_but_not_the_goal(kitchen, library):
    plans, _ = planner({"microwave": MICROWAVE_UNPLUGGED}, library, ground=False)
    done = planned_trial(kitchen, plans, find_task("microwave-potato"))
    assert done.rollout.verdict.value == "satisfied" and not done.success
    assert [(c.text(), ok) for c, ok in done.goal.conditions] == [("Potato: isCooked = true", False)]


@pytest.fixture
def scripted_planner(monkeypatch, library):
    """`cook2ltl rollout TASK` plans with the scripted model instead of the production models."""
    @contextmanager
    def fake(model, library_path, variant, validate, repairs, ground):
        asked.append((validate, repairs))
        yield planner({"microwave": MICROWAVE, "refrigerate": "pick_up(apple)\nput(apple, fridge)"}, library,
                      ground)[0]

    asked = []
    monkeypatch.setattr(planning, "open_planner", fake)
    return asked


@pytest.fixture
def launched(monkeypatch, thor_home):
    """Every Controller the command starts, to check it was stopped."""
    started = []
    real = launcher.start_kitchen

    def recording(*args, **kwargs):
        started.append(real(*args, **kwargs))
        return started[-1]

    monkeypatch.setattr(launcher, "start_kitchen", recording)
    return started


def test_the_command_plans_runs_and_reports_json(scripted_planner, launched):
    result = runner.invoke(app, ["rollout", "Microwave the potato", "--json"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.output)
    assert report["task"]["id"] == "microwave-potato" and report["backend"] == "embedded"
    assert report["plan"]["calls"][0] == "pick_up(potato)" and report["plan"]["sources"] == ["llm"]
    assert [s["action"] for s in report["trace"]] == ["pick_up(potato)", "open(microwave)", "put(potato, microwave)",
                                                     "close(microwave)", "turn_on(microwave)", "turn_off(microwave)"]
    assert report["trace"][4]["facts"] == [] and report["trace"][4]["remaining"] == 'F"turn_off(microwave)"'
    assert report["trace"][0]["thor"][-1]["action"] == "PickupObject"
    assert report["verdict"] == "satisfied" and report["goal"]["met"] and report["success"]
    assert report["seconds"]["total"] == pytest.approx(report["seconds"]["plan"] + report["seconds"]["rollout"],
                                                       abs=0.01)
    assert [stopped(c) for c in launched] == [True]
    assert scripted_planner == [(True, 2)]  # new reductions are checked in the kitchen by default
    runner.invoke(app, ["rollout", "Microwave the potato", "--json", "--no-validate", "--repairs", "1"])
    assert scripted_planner[-1] == (False, 1)


def test_the_command_shows_a_failed_plan_live_and_exits_1(scripted_planner, launched):
    result = runner.invoke(app, ["rollout", "refrigerate-apple", "--no-ground"])
    assert result.exit_code == 1
    assert "✓ pick_up(apple)" in result.output
    assert "✗ put(apple, fridge): Fridge|-02.10|+00.00|+01.07 is closed" in result.output
    assert "goal    ✗ Apple: in = Fridge, temperature = Cold" in result.output
    assert stopped(launched[0])


def test_the_command_runs_a_formula_or_a_reference_plan_without_a_model(launched):
    formula = runner.invoke(app, ["rollout", "F(pick_up(mug) & F put(mug, sink))", "--scene", "FloorPlan7", "--json"])
    assert formula.exit_code == 0, formula.output
    report = json.loads(formula.output)
    assert report["task"] is None and report["plan"] is None and report["goal"] is None
    assert report["scene"] == "FloorPlan7" and report["verdict"] == "satisfied"
    reference = runner.invoke(app, ["rollout", "toast-bread", "--reference"])
    assert reference.exit_code == 0 and "goal    ✓ Bread: isSliced = true, isCooked = true" in reference.output


def test_the_command_refuses_what_it_cannot_run(launched):
    unknown = runner.invoke(app, ["rollout", "F pick_up(oven)"])
    assert isinstance(unknown.exception, UnknownObject)
    assert stopped(launched[0])  # stopped on an error too
    neither = runner.invoke(app, ["rollout", "make a souffle"])
    assert "neither a task nor a formula" in neither.exception.message
    scene = runner.invoke(app, ["rollout", "F pick_up(apple)", "--scene", "FloorPlan31"])
    assert "no kitchen scene named 'FloorPlan31'" in scene.exception.message


def test_the_thor_backend_says_when_no_build_is_installed(thor_home):
    result = runner.invoke(app, ["rollout", "chop-tomato", "--reference", "--backend", "thor"])
    assert isinstance(result.exception, KitchenUnavailable)
    assert result.exception.message.startswith("THOR unavailable: no AI2-THOR build installed")


def test_the_command_lists_the_tasks():
    result = runner.invoke(app, ["rollout", "--list", "--json"])
    assert result.exit_code == 0
    listed = json.loads(result.output)
    assert listed[0] == {"id": "microwave-potato", "instruction": "Microwave the potato.", "scene": "FloorPlan1",
                         "category": "heat", "source": "paper, Table II", "goal": ["Potato: isCooked = true"]}


def test_the_real_planner_checks_new_reductions_in_the_kitchen_before_caching(tmp_path, launched, monkeypatch):
    monkeypatch.setenv("COOK2LTL_MODEL_CACHE", str(MODEL_CACHE))  # HOME is a temp folder in this module
    require_models("smollm2-135m", "gliner-cook2ltl", "spacy-sm")
    path = tmp_path / "library.sqlite"
    result = runner.invoke(app, ["rollout", "microwave-potato", "--model", "smollm2-135m", "--library", str(path),
                                 "--repairs", "0", "--json"])
    assert result.exit_code in (0, 1), result.output
    store = Library(path)
    checks = {entry.validation for entry in store.entries()}
    store.close()
    assert checks and checks <= {"passed", "failed"}  # never cached unchecked
    assert all(stopped(c) for c in launched)
