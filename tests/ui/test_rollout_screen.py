"""The Rollout screen with the real embedded kitchen behind ai2thor's Controller: a task planned by Algorithm 1
(scripted model) and executed, the current recipe's formula, and a bad formula answered by a dialog."""

from __future__ import annotations

import pytest
from textual.widgets import Checkbox, Input, Select

from cook2ltl.ui.messages import RolloutBegan, RolloutDone, RolloutStepped
from cook2ltl.ui.screens.dialogs import ErrorDialog
from cook2ltl.ui.screens.rollout import RolloutScreen
from cook2ltl.ui.widgets.progress_view import FormulaProgress

from .conftest import FRIDGE_RECIPE, SIZE, once, rows, settle, text

pytest.importorskip("ai2thor")
pytestmark = pytest.mark.anyio
FRIDGE_PLAN = ["open(fridge)", "pick_up(apple)", "put(apple, fridge)", "close(fridge)"]


async def test_a_task_is_planned_then_run_step_by_step_to_its_verdict(make_app, services, model):
    posted = []
    app = make_app()
    async with app.run_test(size=SIZE, message_hook=posted.append) as pilot:
        await pilot.press("f4")
        screen = app.screen
        assert isinstance(screen, RolloutScreen)
        screen.query_one("#target", Select).value = "task:refrigerate-apple"
        assert not screen.query_one("#reference", Checkbox).value
        await pilot.press("ctrl+r")
        await settle(pilot)
        assert model.calls == 1 and services.start_kitchen.calls == 1
        steps = [m for m in once(posted) if isinstance(m, RolloutStepped)]
        assert [m.step.attempt.atom.text for m in steps] == FRIDGE_PLAN
        assert any(isinstance(m, RolloutBegan) for m in posted) and any(isinstance(m, RolloutDone) for m in posted)
        log = rows(screen, "#log")
        assert [row[1:3] for row in log] == [["✓", call] for call in FRIDGE_PLAN]
        assert log[-1][3] == "satisfied" and log[0][3] == "presumably false"
        objects = {row[0]: row for row in rows(screen, "#objects")}
        assert objects["Fridge"][2] == "closed, cold" or objects["Fridge"][2].startswith("closed")
        assert objects["Apple"][1] == "Fridge"
        progress = text(screen.query_one(FormulaProgress))
        assert "refrigerate-apple" in progress and "verdict   satisfied" in progress and "success" in progress
        assert "✓ Apple" in progress  # the goal's condition, checked on THOR object state
        assert text(screen.query_one("#status-text")) == "success: the formula is satisfied, the task's goal holds"
    assert services.start_kitchen.stopped_all()  # the app stops its kitchen when it closes


async def test_the_current_recipe_is_rolled_out_after_translating_it(make_app):
    app = make_app(FRIDGE_RECIPE)
    async with app.run_test(size=SIZE) as pilot:
        app.screen.query_one("#primitives", Select).value = "ai2thor"
        await pilot.press("ctrl+r")
        await settle(pilot)
        await pilot.press("f4")
        screen = app.screen
        screen.query_one("#target", Select).value = "recipe"
        await pilot.press("ctrl+r")
        await settle(pilot)
        assert [row[2] for row in rows(screen, "#log")] == FRIDGE_PLAN
        progress = text(screen.query_one(FormulaProgress))
        assert "verdict   satisfied" in progress


async def test_a_formula_the_kitchen_cannot_run_gets_a_dialog(make_app):
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("f4")
        screen = app.screen
        screen.query_one("#formula", Input).value = "F(pick_up(apple) &"
        await pilot.press("ctrl+r")
        await pilot.pause()
        assert isinstance(app.screen, ErrorDialog) and "Not a formula" in text(app.screen.query_one("#error-message"))
        await pilot.press("escape")
        screen.query_one("#formula", Input).value = "F pick_up(unicorn)"
        await pilot.press("ctrl+r")
        await settle(pilot)
        assert isinstance(app.screen, ErrorDialog)
        assert "unicorn" in text(app.screen.query_one("#error-message"))
