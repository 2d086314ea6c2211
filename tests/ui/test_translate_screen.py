"""The Translate screen driven by keys: a run in a thread worker posting typed messages, the steps, the
reductions (new, primitive, cached), the formulas in both syntaxes, export, opening files, errors, cancel."""

from __future__ import annotations

import json
import threading

import pytest
from textual.widgets import Button, Checkbox, Input, TextArea

from cook2ltl.errors import UserError
from cook2ltl.ui.messages import ActionReduced, RecipeParsed, StepTranslated, TranslationDone, WorkNotice, WorkStopped
from cook2ltl.ui.screens.dialogs import ErrorDialog, PathDialog
from cook2ltl.ui.screens.translate import TranslateScreen
from cook2ltl.ui.widgets.formulas import FormulaList
from cook2ltl.ui.widgets.status import WorkStatus
from cook2ltl.ui.widgets.steps_view import StepsView

from .conftest import BOIL_UNHELD, SIZE, once, rows, settle, text

pytestmark = pytest.mark.anyio


async def test_a_run_shows_steps_reductions_and_formulas(make_app, services, model):
    posted = []
    app = make_app()
    async with app.run_test(size=SIZE, message_hook=posted.append) as pilot:
        assert services.make_spans.calls == services.make_model.calls == 0  # nothing loaded before a run
        await pilot.press("ctrl+r")
        await settle(pilot)
        kinds = [type(m) for m in once(posted) if isinstance(m, (RecipeParsed, ActionReduced, StepTranslated,
                                                                 TranslationDone))]
        assert kinds == [RecipeParsed, ActionReduced, StepTranslated, ActionReduced, StepTranslated,
                         ActionReduced, StepTranslated, TranslationDone]
        screen = app.screen
        steps = text(screen.query_one(StepsView))
        assert "boil(the egg)" in steps and "put(the egg, a bowl)" in steps and "boil(the potato)" in steps
        reductions = rows(screen, "#reductions-table")
        assert [row[2:4] for row in reductions] == [["boil(egg)", "new #1"], ["put(egg, bowl)", "primitive"],
                                              ["boil(potato)", "cached #1"]]
        assert reductions[0][5] == "passed"  # the new reduction ran in the kitchen before it was cached
        assert "pick_up(potato) · put(potato, pot)" in reductions[2][6]  # the library body instantiated
        assert model.calls == 1 and services.make_validator.calls == 1
        assert "3 actions: 1 primitive, 1 cached, 1 by the model" in text(screen.query_one("#reduction-summary"))
        formulas = screen.query_one(FormulaList)
        assert "◇" in text(formulas) and "F(" not in text(formulas)
        await pilot.press("ctrl+l")
        assert "F(" in text(formulas) and "◇" not in text(formulas)
        assert app.translation is not None and len(app.translation.steps) == 3
        assert not screen.busy and not screen.query_one("#run", Button).disabled
    validator = services.make_validator.built[0]
    assert validator._controller is None  # its kitchen was stopped when the app closed


async def test_a_plan_the_kitchen_refuses_is_repaired_and_shown_with_its_problem(make_app, model, services):
    from cook2ltl.library import Library

    model.answers["boil"] = [BOIL_UNHELD, model.answers["boil"]]
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+r")
        await settle(pilot)
        screen = app.screen
        assert rows(screen, "#reductions-table")[0][3:6] == ["new #1 +1 rep.", "0.0", "passed"]
        screen.query_one("#results").active = "reductions"
        screen.query_one("#reductions-table").move_cursor(row=0)
        await pilot.pause()
        detail = text(screen.query_one("#reduction-detail"))
        assert "kitchen check passed" in detail and "attempt 1 (failed the check): put(egg, pot)" in detail
        assert "validated 100%" in text(screen.query_one("#reduction-summary"))
    store = Library(services.library_path)
    assert (store.get(1).validation, store.get(1).body.splitlines()[0]) == ("passed", "pick_up(pot)")
    store.close()


async def test_export_writes_json_and_text(make_app, tmp_path):
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        app.screen.query_one("#validate", Checkbox).value = False
        await pilot.press("ctrl+r")
        await settle(pilot)
        for name in ("out.json", "out.txt"):
            await pilot.press("ctrl+s")
            dialog = app.screen
            assert isinstance(dialog, PathDialog)
            dialog.query_one(Input).value = str(tmp_path / name)
            await pilot.press("enter")
            await pilot.pause()
    exported = json.loads((tmp_path / "out.json").read_text())
    assert [step["text"] for step in exported["steps"]] == ["Boil the egg.", "Put the egg in a bowl.",
                                                           "Boil the potato."]
    assert exported["steps"][0]["actions"][0]["validation"] is None  # the kitchen check was off for this run
    assert exported["stats"]["validated_rate"] is None
    plain = (tmp_path / "out.txt").read_text()
    assert "Boil the potato." in plain and "\x1b[" not in plain


async def test_opening_a_file_loads_the_editor_and_a_missing_one_says_so(make_app, tmp_path):
    recipe = tmp_path / "soup.txt"
    recipe.write_text("Boil the potato.\n")
    app = make_app(text="")
    async with app.run_test(size=SIZE) as pilot:
        for path in (recipe, tmp_path / "missing.txt"):
            await pilot.press("ctrl+o")
            app.screen.query_one(Input).value = str(path)
            await pilot.press("enter")
            await pilot.pause()
        assert isinstance(app.screen, ErrorDialog)
        assert "No recipe file at" in text(app.screen.query_one("#error-message"))
        await pilot.press("escape")
        assert app.screen.query_one("#recipe", TextArea).text == "Boil the potato.\n"
        assert app.recipe_path == recipe


async def test_a_failing_run_shows_a_dialog_not_a_traceback(make_app, services):
    def broken():
        raise UserError("The model 'gliner-cook2ltl' is not provisioned.", "run `make models`.")

    services.make_spans = broken
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+r")
        await settle(pilot)
        dialog = app.screen
        assert isinstance(dialog, ErrorDialog)
        assert "not provisioned" in text(dialog.query_one("#error-message"))
        assert "make models" in text(dialog.query_one("#error-hint"))
        await pilot.press("escape")
        assert isinstance(app.screen, TranslateScreen) and not app.screen.busy
        assert "failed" in text(app.screen.query_one(WorkStatus).query_one("#status-text"))


async def test_an_unexpected_error_is_a_dialog_and_its_traceback_goes_to_a_log(make_app, services, sandbox):
    def broken():
        raise RuntimeError("the span model's tensor has the wrong shape")

    services.make_spans = broken
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+r")
        await settle(pilot)
        assert isinstance(app.screen, ErrorDialog)
        assert text(app.screen.query_one("#error-message")) == "RuntimeError: the span model's tensor has the wrong shape"
        assert "ui-errors.log" in text(app.screen.query_one("#error-hint"))
    log = (sandbox / "data" / "ui-errors.log").read_text()
    assert "Traceback" in log and "wrong shape" in log


async def test_cancel_stops_after_the_current_action(make_app, model):
    entered, release = threading.Event(), threading.Event()
    answer = model.complete

    def slow(*args, **kwargs):
        entered.set()
        release.wait(10)
        return answer(*args, **kwargs)

    model.complete = slow
    posted = []
    app = make_app()
    async with app.run_test(size=SIZE, message_hook=posted.append) as pilot:
        app.screen.query_one("#validate", Checkbox).value = False
        await pilot.press("ctrl+r")
        assert entered.wait(10)
        assert app.screen.busy
        await pilot.press("ctrl+g")
        release.set()
        await settle(pilot)
        assert any(isinstance(m, WorkStopped) for m in posted)
        assert not any(isinstance(m, TranslationDone) for m in posted)
        assert sum(isinstance(m, ActionReduced) for m in once(posted)) == 1
        assert text(app.screen.query_one("#status-text")) == "stopped"


async def test_cancel_stops_the_model_mid_plan_and_caches_nothing(make_app, model, services):
    """The model gets the job's cancel event (LlamaModel checks it after every token and raises)."""
    from cook2ltl.library import Library
    from cook2ltl.reduce.llm import GenerationCancelled

    entered = threading.Event()

    def writing(*args, **kwargs):
        entered.set()
        if model.cancel.wait(10):
            raise GenerationCancelled(f"Cancelled while {model.name} was writing a plan.")
        raise AssertionError("never cancelled")

    model.complete = writing
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+r")
        assert entered.wait(10)
        await pilot.press("ctrl+g")
        await settle(pilot)
        assert not isinstance(app.screen, ErrorDialog)
        assert text(app.screen.query_one("#status-text")) == "stopped" and not app.screen.busy
    store = Library(services.library_path)
    assert store.entries() == ()
    store.close()


async def test_an_empty_recipe_is_not_run(make_app, services):
    app = make_app(text="  ")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+r")
        await pilot.pause()
        assert not app.screen.busy and services.make_spans.calls == 0


async def test_lab_mode_reuses_approved_entries_only(make_app, model, services):
    from cook2ltl.library import Library

    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        app.screen.query_one("#variant").value = "AR+A approved-only"
        await pilot.pause()
        app.screen.query_one("#validate", Checkbox).value = False
        await pilot.press("ctrl+r")
        await settle(pilot)
        # boil(egg) is learnt as a pending entry, so boil(potato) goes to the model again and is not cached.
        assert [row[3] for row in rows(app.screen, "#reductions-table")] == ["new #1", "primitive", "new"]
        assert model.calls == 2
        store = Library(services.library_path)
        store.set_status(1, "approved", by="tester", force=True)
        store.close()
        await pilot.press("ctrl+r")
        await settle(pilot)
        assert [row[3] for row in rows(app.screen, "#reductions-table")] == ["cached #1", "primitive", "cached #1"]
        assert model.calls == 2


async def test_a_labs_primitive_set_and_repairs_come_from_the_settings(make_app, model, services, tmp_path):
    from cook2ltl import paths
    from cook2ltl.domain.settings import TranslateSettings

    recipe_set = (paths.assets_dir() / "primitives" / "recipe.toml").read_text()
    examples = paths.assets_dir() / "prompts" / "recipe.txt"
    robot = tmp_path / "boiling-robot.toml"  # a robot that boils by itself
    assets = paths.assets_dir()
    robot.write_text(recipe_set.replace('"../prompts/recipe.txt"', f'"{examples}"')
                     .replace('"../domains/', f'"{assets}/domains/').replace('"../kitchens/', f'"{assets}/kitchens/')
                     .replace('name = "recipe"', 'name = "boiling-robot"')
                     .replace("[primitives]\n", '[primitives]\nboil = ["what"]\n'))
    model.answers["boil"] = BOIL_UNHELD  # refused by the kitchen, and never repaired: repairs = 0
    app, posted = make_app(translate=TranslateSettings((robot,), repairs=0, ground=False)), []
    async with app.run_test(size=SIZE, message_hook=posted.append) as pilot:
        await pilot.press("ctrl+r")
        await settle(pilot)
        assert [row[3:6] for row in rows(app.screen, "#reductions-table")][0] == ["new #1", "0.0", "failed"]
        assert model.calls == 1
        app.screen.query_one("#primitives").value = str(robot)
        await pilot.press("ctrl+r")
        await settle(pilot)
        # boil is the robot's own now; the kitchen cannot run it, so nothing is checked, with a notice
        assert [row[3] for row in rows(app.screen, "#reductions-table")] == ["primitive"] * 3
        assert model.calls == 1
        assert [m.text for m in once(posted) if isinstance(m, WorkNotice)] == [
            "Not checking new reductions: the kitchen has no action for boil."]
