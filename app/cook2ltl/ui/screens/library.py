"""The Library screen: the action library's entries with their review status, kitchen check and a full-text
search; the chosen entry's body, provenance and every version; approve, reject, edit or undo it.

Every read and write of the SQLite file runs in a thread worker (the library keeps one connection per
thread), and ends by posting the entries as they now are.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual import work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, VerticalScroll
from textual.widgets import DataTable, Footer, Header, Input, Label, Select

from cook2ltl.errors import UserError
from cook2ltl.reduce.validation import CheckStatus
from cook2ltl.text_safety import literal
from cook2ltl.ui.literal import shown
from cook2ltl.ui.messages import EntryHistory, LibraryLoaded, WorkProgress
from cook2ltl.ui.screens.base import WorkScreen
from cook2ltl.ui.screens.dialogs import ConfirmDialog
from cook2ltl.ui.screens.entry_editor import Edited, EntryEditor
from cook2ltl.ui.widgets.entry_detail import EntryDetail, check_content, status_content
from cook2ltl.ui.widgets.status import WorkStatus

if TYPE_CHECKING:
    from cook2ltl.library import Library, LibraryEntry

# (name, width): Textual content cells are not measured by the table, so theirs are fixed.
COLUMNS = (("#", None), ("status", 8), ("kitchen", 9), ("action", None), ("primitives", None), ("v", None),
           ("learnt by", None), ("reviewed by", None))
SHOWN = (("all entries", ""), ("pending review", "pending"), ("approved", "approved"), ("rejected", "rejected"),
         ("failed the kitchen check", "failed"))


class LibraryScreen(WorkScreen):
    JOB = "library-write"
    AUTO_FOCUS = "#entries"  # the review keys (a, r, e, u) act on the table's row
    BINDINGS = [
        Binding("a", "approve", "Approve", id="library.approve"),
        Binding("r", "reject", "Reject", id="library.reject"),
        Binding("e", "edit", "Edit", id="library.edit"),
        Binding("u", "undo", "Undo", id="library.undo"),
        Binding("slash", "search", "Search", id="library.search"),
        Binding("ctrl+r", "reload", "Reload", show=False, id="library.reload"),
    ]
    PALETTE = (
        ("Library: approve the entry", "Mark the selected reduction as reviewed and good", "approve"),
        ("Library: reject the entry", "Never use the selected reduction again", "reject"),
        ("Library: edit the entry", "Rewrite the selected body (checked as you type)", "edit"),
        ("Library: undo the last edit", "Bring back the body before the current one", "undo"),
        ("Library: search", "Full-text search over verbs and bodies", "search"),
        ("Library: reload", "Read the library file again", "reload"),
    )

    def __init__(self) -> None:
        super().__init__()
        self.entries: tuple[LibraryEntry, ...] = ()  # what the search found, before the status filter

    def compose(self) -> ComposeResult:
        yield Header()
        with Horizontal(id="library-top", classes="options"):
            yield Input(placeholder="search verbs and bodies: boil, pick*, \"put($what\" …", id="search")
            yield Select(SHOWN, value="", allow_blank=False, id="shown")
            yield Label("", id="library-count")
        with Horizontal(id="library-body"):
            yield DataTable(id="entries", cursor_type="row")
            with VerticalScroll(id="entry-pane"):
                yield EntryDetail(id="entry-detail")
        yield WorkStatus()
        yield Footer()

    def on_mount(self) -> None:
        table = self.query_one("#entries", DataTable)
        for name, width in COLUMNS:
            table.add_column(name, key=name, width=width)

    def on_screen_resume(self) -> None:
        self.action_reload()  # a translation may have added entries meanwhile

    @property
    def library(self) -> Library:
        return self.app.services.library()

    # --- reading ---------------------------------------------------------------------------------------

    def action_reload(self, select: int | None = None) -> None:
        self.load(self.query_one("#search", Input).value, select)

    @work(thread=True, exclusive=True, exit_on_error=False, group="library-read")
    def load(self, query: str, select: int | None = None) -> None:
        try:
            entries, problem = self.library.search(query), ""
        except UserError as error:  # a half-typed query: say so beside the box, keep the last result
            entries, problem = None, error.message
        self.post_message(LibraryLoaded(entries, select, problem))

    @work(thread=True, exclusive=True, exit_on_error=False, group="library-history")
    def load_history(self, entry_id: int) -> None:
        library = self.library
        self.post_message(EntryHistory(entry_id, library.history(entry_id), library.reviews(entry_id)))

    def on_input_changed(self, event: Input.Changed) -> None:
        if event.input.id == "search":
            self.load(event.value)

    def on_select_changed(self, event: Select.Changed) -> None:
        if event.select.id == "shown":
            self._fill_table()

    def action_search(self) -> None:
        self.query_one("#search", Input).focus()

    def on_library_loaded(self, message: LibraryLoaded) -> None:
        count = self.query_one("#library-count", Label)
        if message.entries is None:
            count.update(shown(message.problem).stylize("$text-warning"))
            return
        self.entries = message.entries
        self._fill_table(message.select)

    def _fill_table(self, select: int | None = None) -> None:
        table = self.query_one("#entries", DataTable)
        current = self.selected()
        select = select if select is not None else (current.id if current else None)
        listed = [entry for entry in self.entries if self._wanted(entry)]
        table.clear()
        for entry in listed:
            table.add_row(str(entry.id), status_content(entry.status.value), check_content(entry.validation),
                          literal(entry.action), literal(entry.primitives), str(entry.version), literal(entry.model),
                          literal(entry.reviewed_by or ""), key=str(entry.id))
        self.query_one("#library-count", Label).update(
            shown(f"{len(listed)} shown · {self.app.services.library_path.name}"))
        ids = [entry.id for entry in listed]
        if select in ids:
            table.move_cursor(row=ids.index(select))
        self._show_selected()

    def _wanted(self, entry: LibraryEntry) -> bool:
        wanted = self.query_one("#shown", Select).value
        return not wanted or wanted in (entry.status.value, entry.validation)

    def on_data_table_row_highlighted(self, _: DataTable.RowHighlighted) -> None:
        self._show_selected()

    def _show_selected(self) -> None:
        entry = self.selected()
        self.query_one(EntryDetail).show(entry)
        if entry is not None:
            self.load_history(entry.id)

    def on_entry_history(self, message: EntryHistory) -> None:
        entry = self.selected()
        if entry is not None and entry.id == message.entry_id:
            self.query_one(EntryDetail).show(entry, message.versions, message.reviews)

    def selected(self) -> LibraryEntry | None:
        table = self.query_one("#entries", DataTable)
        if not table.row_count:
            return None
        key = table.coordinate_to_cell_key(table.cursor_coordinate).row_key.value
        return next((entry for entry in self.entries if str(entry.id) == key), None)

    # --- reviewing -------------------------------------------------------------------------------------

    def action_approve(self) -> None:
        entry = self._reviewable()
        if entry is None:
            return
        if not entry.has_plan:
            self.notify(f"#{entry.id} has no plan: nothing to approve. Edit it to write its body.", severity="warning")
            return
        if entry.validation != CheckStatus.FAILED:
            self._write(f"approving #{entry.id}", entry.id, "approve")
            return

        def confirmed(yes: bool | None) -> None:
            if yes:
                self._write(f"approving #{entry.id}", entry.id, "approve", True)

        self.app.push_screen(ConfirmDialog(
            f"#{entry.id} failed the kitchen check", "\n".join(entry.problems) or "no details",
            "Approve it anyway?", "Approve anyway"), confirmed)

    def action_reject(self) -> None:
        entry = self._reviewable()
        if entry is not None:
            self._write(f"rejecting #{entry.id}", entry.id, "reject")

    def action_undo(self) -> None:
        entry = self._reviewable()
        if entry is not None:
            self._write(f"undoing the last edit of #{entry.id}", entry.id, "undo")

    def action_edit(self) -> None:
        entry = self._reviewable()
        if entry is None:
            return

        def saved(edited: Edited | None) -> None:
            if edited is not None and edited.body != entry.body:
                self._write(f"saving version {entry.version + 1} of #{entry.id}", entry.id, "edit", (edited, entry))

        self.app.push_screen(EntryEditor(entry), saved)

    def _reviewable(self) -> LibraryEntry | None:
        entry = self.selected()
        if entry is None or self.busy:
            return None
        if entry.status.value == "rejected":
            self.notify(f"#{entry.id} is rejected: it stays as history and is never used.", severity="warning")
            return None
        return entry

    def _write(self, what: str, entry_id: int, change: str, argument: object = None) -> None:
        query = self.query_one("#search", Input).value
        self.begin(f"{what} …")
        self.change(entry_id, change, argument, query)

    @work(thread=True, exclusive=True, exit_on_error=False, group=JOB)
    def change(self, entry_id: int, change: str, argument: object, query: str) -> None:
        from cook2ltl.library import Status, reviewer  # startup: the app opens before the library (sqlite-utils) loads

        library, by = self.library, reviewer()
        if change == "approve":
            entry = library.set_status(entry_id, Status.APPROVED, by, force=bool(argument))
        elif change == "reject":
            entry = library.set_status(entry_id, Status.REJECTED, by)
        elif change == "undo":
            entry = library.undo(entry_id, by)
        else:
            edited, read = argument  # saved only if nobody approved or edited the entry since it was read
            entry = library.edit(entry_id, edited.body, by, edited.check.validation, edited.check.problems,
                                 note="edited in the app", expected=read)
        self.post_message(LibraryLoaded(library.search(query), entry_id))
        self.post_message(WorkProgress(f"#{entry.id} {entry.action}: {entry.status.value}, version {entry.version}"))
