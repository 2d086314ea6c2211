"""The Library screen: the action library's entries with their review status and a search; the selected
entry's body, provenance and versions; approve, reject, or edit it (an edit replaces the entry)."""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING

from textual import work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, VerticalScroll
from textual.content import Content
from textual.widgets import DataTable, Footer, Header, Input, Label, Static

from cook2ltl.ui.messages import LibraryLoaded
from cook2ltl.ui.screens.base import WorkScreen
from cook2ltl.ui.screens.entry_editor import EntryEditor
from cook2ltl.ui.widgets.status import WorkStatus

if TYPE_CHECKING:
    from cook2ltl.library import LibraryEntry

EDITED = "edited by hand"  # the model column of a body a reviewer wrote
STATUS_STYLE = {"pending": "$text-warning", "approved": "$text-success", "rejected": "$text-error"}
COLUMNS = ("#", "status", "primitives", "action", "written by", "created")


class LibraryScreen(WorkScreen):
    BINDINGS = [
        Binding("a", "approve", "Approve", id="library.approve"),
        Binding("r", "reject", "Reject", id="library.reject"),
        Binding("e", "edit", "Edit", id="library.edit"),
        Binding("slash", "search", "Search", id="library.search"),
        Binding("ctrl+r", "reload", "Reload", id="library.reload"),
    ]
    PALETTE = (
        ("Library: approve the entry", "Mark the selected reduction as reviewed and good", "approve"),
        ("Library: reject the entry", "Never use the selected reduction again", "reject"),
        ("Library: edit the entry", "Rewrite the selected body (checked as you type)", "edit"),
        ("Library: search", "Filter the entries by any words", "search"),
        ("Library: reload", "Read the library file again", "reload"),
    )

    def __init__(self) -> None:
        super().__init__()
        self.entries: tuple[LibraryEntry, ...] = ()

    def compose(self) -> ComposeResult:
        yield Header()
        with Horizontal(id="library-top", classes="options"):
            yield Input(placeholder="search: verb, body, status, model …", id="search")
            yield Label("", id="library-count")
        with Horizontal(id="library-body"):
            yield DataTable(id="entries", cursor_type="row")
            with VerticalScroll(id="entry-detail"):
                yield Static("", id="entry-body")
                yield Static("", id="entry-provenance")
                yield Static("", id="entry-history")
        yield WorkStatus()
        yield Footer()

    def on_mount(self) -> None:
        table = self.query_one("#entries", DataTable)
        for name in COLUMNS:
            table.add_column(name, key=name)
        self.action_reload()

    def on_screen_resume(self) -> None:
        self.action_reload()  # a translation may have added entries meanwhile

    # --- reading and writing, in a worker --------------------------------------------------------------

    def action_reload(self, select: int | None = None) -> None:
        if not self.busy:
            self.load(self.begin("reading the library …"), select)

    @work(thread=True, exclusive=True, exit_on_error=False, group="library")
    def load(self, cancel: threading.Event, select: int | None) -> None:
        self.post_message(LibraryLoaded(self.app.services.library().entries(), select))

    @work(thread=True, exclusive=True, exit_on_error=False, group="library")
    def set_status(self, cancel: threading.Event, entry_id: int, status: str) -> None:
        library = self.app.services.library()
        library.set_status(entry_id, status)
        self.post_message(LibraryLoaded(library.entries(), entry_id))

    @work(thread=True, exclusive=True, exit_on_error=False, group="library")
    def replace_body(self, cancel: threading.Event, entry: LibraryEntry, body: str) -> None:
        from cook2ltl.library import Status

        library = self.app.services.library()
        new = library.add(entry.primitives, entry.verb, entry.signature, body, EDITED, entry.prompt_hash,
                          replacing=entry.id)
        if new.body == body:  # else another process stored its own version first: left for review
            library.set_status(new.id, Status.APPROVED)  # a reviewer wrote it
        self.post_message(LibraryLoaded(library.entries(), new.id))

    def on_library_loaded(self, message: LibraryLoaded) -> None:
        self.entries = message.entries
        self.query_one(WorkStatus).show(f"{self.app.services.library_path}")
        self._fill_table(message.select)

    # --- the table and the detail pane -----------------------------------------------------------------

    def on_input_changed(self, event: Input.Changed) -> None:
        if event.input.id == "search":
            self._fill_table()

    def action_search(self) -> None:
        self.query_one("#search", Input).focus()

    def _fill_table(self, select: int | None = None) -> None:
        table = self.query_one("#entries", DataTable)
        current = self.selected()
        select = select if select is not None else (current.id if current else None)
        words = self.query_one("#search", Input).value.lower().split()
        shown = [e for e in self.entries if all(word in _haystack(e) for word in words)]
        table.clear()
        for entry in shown:
            table.add_row(str(entry.id), _status(entry.status.value), entry.primitives, _action(entry), entry.model,
                          entry.created[:10], key=str(entry.id))
        self.query_one("#library-count", Label).update(f"{len(shown)} of {len(self.entries)} entries")
        ids = [entry.id for entry in shown]
        if select in ids:
            table.move_cursor(row=ids.index(select))
        self._show_detail(self.selected())

    def on_data_table_row_highlighted(self, _: DataTable.RowHighlighted) -> None:
        self._show_detail(self.selected())

    def selected(self) -> LibraryEntry | None:
        table = self.query_one("#entries", DataTable)
        if not table.row_count:
            return None
        key = table.coordinate_to_cell_key(table.cursor_coordinate).row_key.value
        return next((entry for entry in self.entries if str(entry.id) == key), None)

    def _show_detail(self, entry: LibraryEntry | None) -> None:
        body, provenance, history = (self.query_one(f"#entry-{part}", Static) for part in ("body", "provenance",
                                                                                            "history"))
        if entry is None:
            body.update("No entry: the library grows as translations reduce actions with the model.")
            provenance.update("")
            history.update("")
            return
        body.update(Content(f"{_action(entry)}\n").stylize("bold") + Content(entry.body))
        provenance.update(Content("\n").join([
            Content("provenance").stylize("bold"),
            Content("status        ") + _status(entry.status.value),
            Content(f"primitive set {entry.primitives}"),
            Content(f"written by    {entry.model}"),
            Content(f"prompt        {entry.prompt_hash[:16] or '—'}"),
            Content(f"created       {entry.created}"),
        ]))
        versions = [e for e in self.entries if (e.primitives, e.verb, e.signature) ==
                    (entry.primitives, entry.verb, entry.signature)]
        lines = [Content("versions of this action").stylize("bold")]
        for version in versions:
            mark = "▶ " if version.id == entry.id else "  "
            lines.append(Content(f"{mark}#{version.id} ") + _status(version.status.value)
                         + Content(f"  {version.model} · {version.created}"))
        lines.append(Content("an edit or a replacement adds a version and rejects the one before; the library does "
                             "not record when a status changed or who changed it").stylize("$text-muted"))
        history.update(Content("\n").join(lines))

    # --- review actions --------------------------------------------------------------------------------

    def action_approve(self) -> None:
        self._review("approved")

    def action_reject(self) -> None:
        self._review("rejected")

    def _review(self, status: str) -> None:
        entry = self.selected()
        if entry is None or self.busy:
            return
        if entry.status.value == status:
            self.notify(f"#{entry.id} is already {status}.")
            return
        live = self._live_version(entry)
        if status == "approved" and live is not None and live.id != entry.id:
            self.notify(f"#{live.id} is the live version of this action; reject it first.", severity="warning")
            return
        self.set_status(self.begin(f"marking #{entry.id} {status} …"), entry.id, status)

    def action_edit(self) -> None:
        from cook2ltl.reduce.reduction import LibraryVerb

        entry = self.selected()
        if entry is None or self.busy:
            return
        if entry.status.value == "rejected":
            self.notify("Rejected entries are kept as history; edit the live version.", severity="warning")
            return
        verbs = [LibraryVerb(e.verb, e.signature, e.body) for e in self.entries
                 if e.primitives == entry.primitives and e.status.value != "rejected"]

        def saved(body: str | None) -> None:
            if body is not None and body != entry.body:
                self.replace_body(self.begin(f"saving the new version of #{entry.id} …"), entry, body)

        self.app.push_screen(EntryEditor(entry, verbs), saved)

    def _live_version(self, entry: LibraryEntry) -> LibraryEntry | None:
        return next((e for e in self.entries if (e.primitives, e.verb, e.signature) ==
                     (entry.primitives, entry.verb, entry.signature) and e.status.value != "rejected"), None)


def _action(entry: LibraryEntry) -> str:
    return f"{entry.verb}({', '.join(entry.signature)})"


def _status(status: str) -> Content:
    return Content(status).stylize(STATUS_STYLE[status])


def _haystack(entry: LibraryEntry) -> str:
    return " ".join((str(entry.id), entry.status.value, entry.primitives, _action(entry), entry.model,
                     entry.body)).lower()
