"""SVG snapshots of each screen at a fixed size (tests/ui/__snapshots__; `--snapshot-update` rewrites them after a
deliberate change). Nothing in view depends on the clock or the machine: the clocks behind the shown timings are
frozen and the library's timestamps fixed."""

from __future__ import annotations

import sqlite3
from types import SimpleNamespace

import pytest
from textual.widgets import Select

from cook2ltl.library import Library
from cook2ltl.library.schema import TABLE, VERSIONS

from .conftest import FRIDGE_RECIPE, SIZE, settle

FROZEN = SimpleNamespace(perf_counter=lambda: 0.0)


@pytest.fixture
def frozen_clocks(monkeypatch):
    import cook2ltl.execution.rollout
    import cook2ltl.pipeline.translator

    monkeypatch.setattr(cook2ltl.pipeline.translator, "time", FROZEN)
    monkeypatch.setattr(cook2ltl.execution.rollout, "time", FROZEN)


async def steady_cursor(pilot) -> None:
    """The editor's cursor blinks: on or off would depend on the moment of the picture."""
    pilot.app.screen.query_one("#recipe").cursor_blink = False


def test_translate_after_a_run(snap_compare, make_app, frozen_clocks):
    async def run(pilot):
        await steady_cursor(pilot)
        await pilot.press("ctrl+r")
        await settle(pilot)

    assert snap_compare(make_app(), terminal_size=SIZE, run_before=run)


def test_translate_reductions(snap_compare, make_app, frozen_clocks):
    async def run(pilot):
        await steady_cursor(pilot)
        await pilot.press("ctrl+r")
        await settle(pilot)
        pilot.app.screen.query_one("#results").active = "reductions"
        await pilot.pause()

    assert snap_compare(make_app(), terminal_size=SIZE, run_before=run)


def test_library_with_a_failed_check_chosen(snap_compare, make_app, services):
    store = Library(services.library_path)
    store.add("recipe", "boil", ("what",), "pick_up($what)\nput($what, pot)\nturn_on(stovetop)", "qwen", "3f2a9c",
              validation="passed", example={"$what": "egg"})
    fry = store.add("recipe", "fry", ("what",), "put($what, pan)\nturn_on(stovetop)", "qwen", "77b1e0",
                    validation="failed", problems=("line 1 put(egg, pan): not holding egg",), example={"$what": "egg"})
    store.edit(fry.id, "pick_up($what)\nput($what, pan)\nturn_on(stovetop)", "ada", "failed",
               ("line 3 turn_on(stovetop): the pan is not on the stove",), note="picks the egg up first")
    store.close()
    with sqlite3.connect(services.library_path) as db:  # the times the entries were learnt and edited, fixed
        db.execute(f"UPDATE {TABLE} SET created = '2026-05-01T09:00:00+00:00'")
        db.execute(f"UPDATE {VERSIONS} SET at = '2026-05-0' || version || 'T10:00:00+00:00'")

    async def run(pilot):
        await pilot.press("f3")
        await settle(pilot)
        await pilot.press("down")
        await settle(pilot)

    assert snap_compare(make_app(), terminal_size=SIZE, run_before=run)


def test_rollout_of_the_translated_recipe(snap_compare, make_app, frozen_clocks):
    async def run(pilot):
        await steady_cursor(pilot)
        pilot.app.screen.query_one("#primitives", Select).value = "ai2thor"
        await pilot.press("ctrl+r")
        await settle(pilot)
        await pilot.press("f4")
        pilot.app.screen.query_one("#target", Select).value = "recipe"
        await pilot.press("ctrl+r")
        await settle(pilot)

    assert snap_compare(make_app(FRIDGE_RECIPE), terminal_size=SIZE, run_before=run)


def test_help(snap_compare, make_app):
    async def run(pilot):
        await steady_cursor(pilot)
        await pilot.press("f1")

    assert snap_compare(make_app(), terminal_size=SIZE, run_before=run)
