"""The editor of one library body, with the problems that would stop the pipeline from using it shown inline
as you type; Save stays disabled until there are none."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.content import Content
from textual.screen import ModalScreen
from textual.widgets import Button, Label, Static, TextArea

from cook2ltl.errors import UserError

if TYPE_CHECKING:
    from cook2ltl.library import LibraryEntry
    from cook2ltl.reduce.reduction import LibraryVerb


class EntryEditor(ModalScreen[str | None]):
    """Dismissed with the new body, or None when cancelled."""

    BINDINGS = [
        Binding("ctrl+s", "save", "Save", id="editor.save"),
        Binding("escape", "dismiss(None)", "Cancel", id="editor.cancel"),
    ]

    def __init__(self, entry: LibraryEntry, verbs: list[LibraryVerb]) -> None:
        super().__init__(classes="dialog")
        self.entry, self.verbs = entry, verbs
        self.problems: list[str] = []

    def compose(self) -> ComposeResult:
        from cook2ltl.reduce.body import bind

        entry = self.entry
        parameters = ", ".join(bind(entry.signature, entry.signature)) or "no parameters"
        with Vertical(id="entry-editor", classes="dialog-box"):
            yield Label(f"Edit #{entry.id}: {entry.verb}({', '.join(entry.signature)}) in {entry.primitives}",
                        classes="dialog-title")
            yield Static(Content(f"one call per line; parameters: {parameters}").stylize("$text-muted"))
            yield TextArea(entry.body, id="body")
            yield Static("", id="problems")
            with Horizontal(classes="dialog-buttons"):
                yield Button("Save", variant="primary", id="save")
                yield Button("Cancel", id="cancel")

    def on_mount(self) -> None:
        self.check()

    def on_text_area_changed(self) -> None:
        self.check()

    def check(self) -> None:
        from cook2ltl.reduce.primitives import load_primitives
        from cook2ltl.library.body_check import body_problems

        body = self.query_one("#body", TextArea).text
        try:
            primitives = load_primitives(self.entry.primitives)
        except UserError as error:
            self.problems = [f"cannot check against the primitive set {self.entry.primitives!r}: {error.message}"]
        else:
            self.problems = body_problems(body, self.entry.verb, self.entry.signature, primitives, self.verbs)
        shown = self.query_one("#problems", Static)
        if self.problems:
            shown.update(Content("\n").join(Content(f"✗ {p}").stylize("$text-error") for p in self.problems))
        else:
            shown.update(Content("✓ the pipeline can use this body").stylize("$text-success"))
        self.query_one("#save", Button).disabled = bool(self.problems)

    def on_button_pressed(self, event: Button.Pressed) -> None:
        if event.button.id == "save":
            self.action_save()
        else:
            self.dismiss(None)

    def action_save(self) -> None:
        if not self.problems:
            self.dismiss(self.query_one("#body", TextArea).text.strip())
