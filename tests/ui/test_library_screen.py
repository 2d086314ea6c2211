"""The Library screen on a real SQLite library: the table, full-text search and the status filter, the detail
pane with provenance and history, approve (and the confirmation for a failed kitchen check), reject, an edit
checked as you type, and undo."""

from __future__ import annotations

import pytest
from textual.widgets import Button, DataTable, Input, Select, TextArea

from cook2ltl.library import Library, Status
from cook2ltl.ui.screens.dialogs import ConfirmDialog
from cook2ltl.ui.screens.entry_editor import EntryEditor
from cook2ltl.ui.widgets.entry_detail import EntryDetail

from .conftest import SIZE, rows, settle, text

pytestmark = pytest.mark.anyio
FAILED = ("line 1 put(egg, pan): not holding egg",)


@pytest.fixture
def library(services):
    store = Library(services.library_path)
    store.add("recipe", "boil", ("what",), "pick_up($what)\nput($what, pot)\nturn_on(stovetop)", "qwen", "h1",
              validation="passed", example={"$what": "egg"})
    store.add("recipe", "whisk", ("what",), "stir($what)", "qwen", "h2")
    store.add("recipe", "fry", ("what",), "put($what, pan)", "qwen", "h3", validation="failed", problems=FAILED)
    yield store
    store.close()


async def choose(pilot, verb: str) -> None:
    screen = pilot.app.screen
    table = screen.query_one("#entries", DataTable)
    table.move_cursor(row=[row[3] for row in rows(screen, "#entries")].index(f"{verb}(what)"))
    table.focus()
    await settle(pilot)


async def test_entries_search_filter_and_detail(make_app, library):
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("f3")
        await settle(pilot)
        screen = app.screen
        assert [row[:4] for row in rows(screen, "#entries")] == [["1", "pending", "passed", "boil(what)"],
                                                     ["2", "pending", "unchecked", "whisk(what)"],
                                                     ["3", "pending", "failed", "fry(what)"]]
        detail = text(screen.query_one(EntryDetail))
        assert "put($what, pot)" in detail and "$what = egg" in detail and "v1" in detail and "learnt" in detail
        await pilot.press("slash", *"stir")
        await settle(pilot)
        assert [row[3] for row in rows(screen, "#entries")] == ["whisk(what)"]  # found by its body
        screen.query_one("#search", Input).value = 'put($'  # not an FTS query: said beside the box
        await settle(pilot)
        assert "Cannot search" in text(screen.query_one("#library-count"))
        assert [row[3] for row in rows(screen, "#entries")] == ["whisk(what)"]
        screen.query_one("#search", Input).value = ""
        await settle(pilot)
        screen.query_one("#shown", Select).value = "failed"
        await pilot.pause()
        assert [row[3] for row in rows(screen, "#entries")] == ["fry(what)"]
        assert "not holding egg" in text(screen.query_one(EntryDetail))


async def test_approve_reject_and_a_failed_check_needs_confirming(make_app, library):
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("f3")
        await settle(pilot)
        await choose(pilot, "boil")
        await pilot.press("a")
        await settle(pilot)
        approved = library.get(1)
        assert approved.status == Status.APPROVED and approved.reviewed_by == "tester"
        assert rows(app.screen, "#entries")[0][1] == "approved" and rows(app.screen, "#entries")[0][7] == "tester"
        assert "approved by tester at" in text(app.screen.query_one(EntryDetail))  # the review log, per version
        await choose(pilot, "fry")
        await pilot.press("a")
        assert isinstance(app.screen, ConfirmDialog)
        await pilot.press("escape")
        await settle(pilot)
        assert library.get(3).status == Status.PENDING
        await pilot.press("a")
        await pilot.click("#confirm")
        await settle(pilot)
        assert library.get(3).status == Status.APPROVED
        await choose(pilot, "whisk")
        await pilot.press("r")
        await settle(pilot)
        assert library.get(2).status == Status.REJECTED
        await pilot.press("e")  # a rejected entry stays as history
        assert not isinstance(app.screen, EntryEditor)


async def test_an_edit_is_checked_as_you_type_saved_as_a_version_and_undone(make_app, library):
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("f3")
        await settle(pilot)
        await choose(pilot, "whisk")
        await pilot.press("e")
        editor = app.screen
        assert isinstance(editor, EntryEditor)
        await settle(pilot)
        body = editor.query_one("#body", TextArea)
        body.text = "stir($where)\nfold($what)"
        await pilot.pause()
        problems = text(editor.query_one("#problems"))
        assert "$where is not a parameter" in problems and "fold with 1 argument(s)" in problems
        assert editor.query_one("#save", Button).disabled
        body.text = "pick_up($what)\nstir($what)"
        await pilot.pause()
        assert "✓" in text(editor.query_one("#problems"))
        await pilot.press("ctrl+s")
        await settle(pilot)
        edited = library.get(2)
        assert edited.body == "pick_up($what)\nstir($what)" and edited.version == 2
        assert edited.status == Status.PENDING and edited.reviewed_by is None
        assert [(v.version, v.author) for v in library.history(2)] == [(1, "qwen"), (2, "tester")]
        assert edited.validation == "unchecked"  # learnt before examples were kept: nothing to run it with
        assert "v2" in text(app.screen.query_one(EntryDetail))
        await pilot.press("u")
        await settle(pilot)
        assert library.get(2).body == "stir($what)" and library.get(2).version == 3


async def test_save_runs_the_body_in_the_kitchen_and_a_refused_body_needs_a_second_save(make_app, library):
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("f3")
        await settle(pilot)
        await choose(pilot, "boil")  # learnt for boil(egg): the kitchen runs the body with $what = egg
        await pilot.press("e")
        editor = app.screen
        await settle(pilot)
        editor.query_one("#body", TextArea).text = "put($what, pot)\nturn_on(stovetop)"
        await pilot.pause()
        await pilot.press("ctrl+s")
        await settle(pilot)
        assert app.screen is editor  # not saved yet: the kitchen refused a line
        assert "line 1 put(egg, pot): the agent holds nothing" in text(editor.query_one("#problems"))
        assert str(editor.query_one("#save", Button).label) == "Save failing body"
        await pilot.press("ctrl+s")
        await settle(pilot)
        kept = library.get(1)
        assert kept.version == 2 and kept.validation == "failed" and "holds nothing" in kept.problems[0]
        await pilot.press("e")
        await settle(pilot)
        app.screen.query_one("#body", TextArea).text = ("pick_up(pot)\nput(pot, stovetop)\npick_up($what)\n"
                                                        "put($what, pot)\nturn_on(stovetop)\nwait($what == boiled)")
        await pilot.pause()
        await pilot.press("ctrl+s")
        await settle(pilot)
        assert (library.get(1).version, library.get(1).validation) == (3, "passed")


async def test_an_entry_without_a_plan_is_shown_and_cannot_be_approved(make_app, library):
    melt = library.add("recipe", "melt", ("what",), "", "qwen", "h4", validation="failed",
                       problems=("the model wrote no admissible plan",))
    app = make_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("f3")
        await settle(pilot)
        await choose(pilot, "melt")
        detail = text(app.screen.query_one(EntryDetail))
        assert "(no plan)" in detail and "no admissible plan" in detail
        await pilot.press("a")
        await settle(pilot)
        assert not isinstance(app.screen, ConfirmDialog)  # nothing to approve, so nothing to confirm
        assert library.get(melt.id).status == Status.PENDING


async def test_hostile_text_in_the_library_is_shown_literally(make_app, services):
    """Markup and control sequences in every field of every entry (an imported or hand-edited library): the
    table, each entry's detail and history, the editor and a notification show them as text; nothing raises
    and no control character is drawn."""
    from cook2ltl.text_safety import visible
    from tests.reliability.test_fuzz_output import OBEYED
    from tests.reliability.test_injection import HOSTILE, hostile_library

    hostile_library(services.library_path)
    app = make_app()
    async with app.run_test(size=(200, 50)) as pilot:
        await pilot.press("f3")
        await settle(pilot)
        screen = app.screen
        table = rows(screen, "#entries")
        assert visible(f"qwen {HOSTILE}") in [row[6] for row in table] and visible(HOSTILE) in [row[4] for row in table]
        assert visible(f"ann {HOSTILE}") in [row[7] for row in table]
        assert visible('bad"verb(what)') in [row[3] for row in table]
        details = ""
        for index in range(len(table)):
            screen.query_one("#entries", DataTable).move_cursor(row=index)
            await settle(pilot)
            details += text(screen.query_one(EntryDetail))
            assert not OBEYED.search(app.export_screenshot())
        for shown in (f"line 1 {HOSTILE}", f"egg {HOSTILE}", f"bob {HOSTILE}", f"because {HOSTILE}", HOSTILE):
            assert visible(shown) in details, shown
        assert not OBEYED.search(details)
        await choose(pilot, "boil")
        await pilot.press("e")
        await settle(pilot)
        assert isinstance(app.screen, EntryEditor) and not OBEYED.search(app.export_screenshot())
        await pilot.press("escape")
        app.notify(HOSTILE, title=HOSTILE)
        await pilot.pause()
        assert not OBEYED.search(app.export_screenshot())
