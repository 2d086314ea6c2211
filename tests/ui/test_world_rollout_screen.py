"""The Rollout screen runs a recipe in the world model: the current translation as it is, or a recipe file opened
with ctrl+o and translated first; every plan line in the log with its writer, the formula's progress, the
problems by step and the verdict."""

from __future__ import annotations

import pytest
from textual.widgets import Input, Select

from cook2ltl.domain.settings import TranslateSettings
from cook2ltl.ui.messages import (
    RecipeActionRolled,
    RecipeRolloutBegan,
    RecipeRolloutDone,
    RecipeStepRolled,
)
from cook2ltl.ui.screens.dialogs import PathDialog
from cook2ltl.ui.screens.rollout import FILE, WORLD, RolloutScreen
from cook2ltl.ui.widgets.progress_view import FormulaProgress
from tests.translate.test_world_rollout import ANSWERS, PASTA, SPANS

from .conftest import SIZE, once, rows, settle, text

pytestmark = pytest.mark.anyio
LINES = [["1.1", "✓", "pick_up(pot) · model"], ["1.2", "✓", "put(pot, stovetop) · model"],
         ["1.3", "✓", "pick_up(pasta) · model"], ["1.4", "✓", "put(pasta, pot) · model"],
         ["1.5", "✓", "turn_on(stovetop) · model"], ["1.6", "✓", "wait(pasta == cooked) · model"],
         ["2.1", "✓", "pick_up(pot) · model"], ["2.2", "✓", "pour(pot, colander) · planner"]]


@pytest.fixture
def pasta(monkeypatch, model):
    import tests.ui.conftest

    for sentence, spans in SPANS.items():
        monkeypatch.setitem(tests.ui.conftest.SPANS, sentence, spans)
    model.answers.update(ANSWERS)


def lines(screen) -> list[list[str]]:
    return [row[:3] for row in rows(screen, "#log") if "." in row[0]]


async def test_the_translated_recipe_runs_line_by_line_in_the_world_model(make_app, services, pasta):
    posted = []
    app = make_app(PASTA, translate=TranslateSettings(ground=True))
    async with app.run_test(size=SIZE, message_hook=posted.append) as pilot:
        await pilot.press("ctrl+r")
        await settle(pilot)
        await pilot.press("f4")
        screen = app.screen
        assert isinstance(screen, RolloutScreen)
        screen.query_one("#target", Select).value = WORLD
        await pilot.press("ctrl+r")
        await settle(pilot)
        messages = once(posted)
        assert sum(isinstance(m, RecipeRolloutBegan) for m in messages) == 1
        assert [m.rolled.run.result.reduction.action.text() for m in messages
                if isinstance(m, RecipeActionRolled)] == ["cook(pasta)", "drain(pasta)"]
        assert [m.run.reached for m in messages if isinstance(m, RecipeStepRolled)] == [True, True]
        done = next(m for m in messages if isinstance(m, RecipeRolloutDone))
        assert done.rollout.success and done.rollout.translation is app.translation
        assert lines(screen) == LINES
        log = rows(screen, "#log")
        assert ["2", "", "Drain the pasta.", "", ""] in log
        assert ["", "", "→ drain(pasta)", "", "effect in(pasta, colander): reached"] in log
        progress = text(screen.query_one(FormulaProgress))
        assert "the recipe · 2 steps, 2 actions · the world model" in progress
        assert "verdict   satisfied" in progress and "success · 2 of 2 steps reached their effects" in progress
        assert text(screen.query_one("#status-text")) == ("success: the formula is satisfied, 2 of 2 steps reached "
                                                          "their effects")
    assert services.start_kitchen.calls == 0  # the world model needs no kitchen


async def test_a_recipe_file_is_translated_then_rolled_out_with_its_problems_by_step(make_app, tmp_path, pasta):
    recipe = tmp_path / "pasta.txt"
    recipe.write_text("Cook the pasta. Put the egg in the fridge.")  # the egg is not in hand, the fridge is shut
    posted = []
    app = make_app("")
    async with app.run_test(size=SIZE, message_hook=posted.append) as pilot:
        await pilot.press("f4")
        screen = app.screen
        await pilot.press("ctrl+o")
        assert isinstance(app.screen, PathDialog)
        app.screen.query_one("#path", Input).value = str(recipe)
        await pilot.press("enter")
        await settle(pilot)
        assert screen.query_one("#target", Select).value == FILE
        assert app.translation is None  # the Translate screen's translation (none yet) is left as it was
        done = next(m for m in once(posted) if isinstance(m, RecipeRolloutDone))
        cook, put = done.rollout.steps
        assert not cook.problems and put.problems[0].startswith("put(egg, fridge): line 1 put(egg, fridge): ")
        progress = text(screen.query_one(FormulaProgress))
        assert "pasta.txt · 2 steps" in progress and f"step 2    ! {put.problems[0]}" in progress
        assert ["", "!", "problem", "", put.problems[0]] in rows(screen, "#log")
