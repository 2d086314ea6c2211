"""The app as a whole: `cook2ltl` with no command opens it, F-keys switch screens, the help screen lists the
bindings, and the command palette offers the main actions of the screen in front."""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

from cook2ltl.cli import app as cli
from cook2ltl.errors import UserError
from cook2ltl.ui.commands import MainCommands
from cook2ltl.ui.screens.help import HelpScreen
from cook2ltl.ui.screens.library import LibraryScreen
from cook2ltl.ui.screens.rollout import RolloutScreen
from cook2ltl.ui.screens.translate import TranslateScreen

from .conftest import SIZE, text

runner = CliRunner()


@pytest.fixture
def opened(monkeypatch):
    """run_app replaced by a recorder: the CLI's wiring, without a terminal."""
    calls = []
    monkeypatch.setattr("cook2ltl.ui.app.run_app", lambda recipe=None: calls.append(recipe))
    return calls


def test_no_command_opens_the_app(opened):
    result = runner.invoke(cli, [])
    assert result.exit_code == 0, result.output
    assert opened == [None]


def test_app_command_opens_a_recipe(opened, tmp_path):
    recipe = tmp_path / "r.txt"
    result = runner.invoke(cli, ["app", str(recipe)])
    assert result.exit_code == 0 and opened == [recipe]
    assert "Usage" in runner.invoke(cli, ["--help"]).output  # help is still there, just not the default


def test_a_missing_recipe_is_a_cli_error_before_the_app_starts(sandbox, tmp_path):
    from cook2ltl.ui.app import run_app

    with pytest.raises(UserError, match="No recipe file"):
        run_app(tmp_path / "missing.txt")
    with pytest.raises(UserError, match="reads its keys from the terminal"):
        run_app("-")


@pytest.mark.anyio
async def test_function_keys_switch_screens_and_help_lists_the_keys(make_app):
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        assert isinstance(app.screen, TranslateScreen)
        await pilot.press("f3")
        assert isinstance(app.screen, LibraryScreen)
        await pilot.press("f4")
        assert isinstance(app.screen, RolloutScreen)
        await pilot.press("f1")
        assert isinstance(app.screen, HelpScreen)
        shown = text(app.screen.query_one("#help-keys"))
        for key, what in (("ctrl+r", "Run"), ("ctrl+l", "Unicode/Spot"), ("a", "Approve"), ("ctrl+g", "Cancel")):
            assert key in shown and what in shown
        await pilot.press("escape")
        await pilot.press("f2")
        assert isinstance(app.screen, TranslateScreen)


@pytest.mark.anyio
async def test_the_palette_offers_the_actions_of_the_screen_in_front(make_app):
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        titles = [title for title, _, _ in MainCommands(app.screen)._commands()]
        assert "Translate: run" in titles and "Go to Library" in titles
        await pilot.press("f3")
        titles = [title for title, _, _ in MainCommands(app.screen)._commands()]
        assert "Library: approve the entry" in titles and "Translate: run" not in titles
        await pilot.press("ctrl+p")
        await pilot.press(*"go to rollout")
        await pilot.press("enter")
        await pilot.pause()
        assert isinstance(app.screen, RolloutScreen)


@pytest.mark.anyio
async def test_a_keymap_from_the_settings_moves_the_keys(make_app):
    app = make_app(keymap={"app.library": "f9", "app.rollout": "ctrl+t"})
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("f3")
        assert isinstance(app.screen, TranslateScreen)  # the old key is free
        await pilot.press("f9")
        assert isinstance(app.screen, LibraryScreen)
        await pilot.press("ctrl+t")
        assert isinstance(app.screen, RolloutScreen)
        await pilot.press("f1")
        shown = text(app.screen.query_one("#help-keys"))
        assert "f9" in shown and "ctrl+t" in shown and "f3 " not in shown  # the help lists the keys in use


def test_a_keymap_naming_no_binding_is_a_clear_error_before_the_app_starts(sandbox, monkeypatch, tmp_path):
    from cook2ltl.ui.app import run_app

    config = tmp_path / "config.toml"
    config.write_text('[keymap]\n"library.aprove" = "y"\n')
    monkeypatch.setenv("COOK2LTL_CONFIG", str(config))
    with pytest.raises(UserError, match="names no binding library.aprove") as raised:
        run_app()
    assert "library.approve" in raised.value.hint
