"""The editor of one library body. What would stop the pipeline from using it is shown inline as you type
(`body_problems`); Save then runs the body in the kitchen with the values of the action it was learnt from
(`recheck`, in a worker) and shows what THOR refused. A body that fails is saved only when asked again."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from textual import work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.content import Content
from textual.screen import ModalScreen
from textual.widgets import Button, Label, Static, TextArea
from textual.worker import Worker, WorkerState

from cook2ltl.errors import UserError
from cook2ltl.reduce.validation import CheckStatus
from cook2ltl.text_safety import visible
from cook2ltl.ui.literal import shown
from cook2ltl.ui.messages import EditorReady, KitchenChecked

if TYPE_CHECKING:
    from cook2ltl.domain.actions import PrimitiveSet
    from cook2ltl.library import LibraryEntry
    from cook2ltl.library.recheck import Recheck
    from cook2ltl.reduce.reduction import LibraryVerb


@dataclass(frozen=True)
class Edited:
    body: str
    check: Recheck  # the kitchen's verdict on it, stored with the new version


class EntryEditor(ModalScreen[Edited | None]):
    """Dismissed with the new body and its kitchen check, or None when cancelled."""

    BINDINGS = [
        Binding("ctrl+s", "save", "Save", id="editor.save"),
        Binding("escape", "dismiss(None)", "Cancel", id="editor.cancel"),
    ]

    def __init__(self, entry: LibraryEntry) -> None:
        super().__init__(classes="dialog")
        self.entry = entry
        self.primitives: PrimitiveSet | None = None
        self.verbs: list[LibraryVerb] = []
        self.problems: list[str] = ["reading the library …"]
        self.failed: Edited | None = None  # a body that failed the kitchen check: Save again keeps it

    def compose(self) -> ComposeResult:
        from cook2ltl.reduce.body import bind  # startup: the app opens before reduce.body (~1.5 ms) loads

        entry = self.entry
        parameters = ", ".join(bind(entry.signature, entry.signature)) or "no parameters"
        example = ", ".join(f"{k} = {v}" for k, v in entry.example) or "no example kept"
        with Vertical(id="entry-editor", classes="dialog-box"):
            yield Label(shown(f"Edit #{entry.id}: {entry.action} in the {entry.primitives} primitives (version "
                              f"{entry.version})"), classes="dialog-title")
            yield Static(shown(f"one call per line; parameters: {parameters}; checked in the kitchen with "
                               f"{example}").stylize("$text-muted"))
            yield TextArea(visible(entry.body), id="body")  # a control in it is shown, and fails the check
            yield Static("", id="problems")
            with Horizontal(classes="dialog-buttons"):
                yield Button("Save", variant="primary", id="save", disabled=True)
                yield Button("Cancel", id="cancel")

    def on_mount(self) -> None:
        self.prepare()

    @work(thread=True, exit_on_error=False, group="editor")
    def prepare(self) -> None:
        """The primitive set and the library verbs a body may call, read once."""
        # startup: the app opens before the library (sqlite-utils) and the primitive sets (pydantic) load
        from cook2ltl.library.recheck import live_verbs
        from cook2ltl.reduce.primitives import load_primitives

        verbs = live_verbs(self.app.services.library(), self.entry.primitives)
        try:
            self.post_message(EditorReady(load_primitives(self.entry.primitives), verbs, ""))
        except UserError as error:
            self.post_message(EditorReady(None, verbs, f"cannot check against the primitive set "
                                                       f"{self.entry.primitives!r}: {error.message}"))

    def on_editor_ready(self, message: EditorReady) -> None:
        self.primitives, self.verbs = message.primitives, message.verbs
        self.check(message.problem)

    def on_text_area_changed(self) -> None:
        if self.primitives is not None:
            self.failed = None
            self.check()

    def check(self, problem: str = "") -> None:
        from cook2ltl.library.body_check import body_problems  # startup: the app opens before the library loads

        body = self.query_one("#body", TextArea).text
        self.problems = [problem] if problem else body_problems(body, self.entry.verb, self.entry.signature,
                                                                self.primitives, self.verbs)
        if self.problems:
            self._show([shown(f"✗ {p}").stylize("$text-error") for p in self.problems])
        else:
            self._show([Content("✓ the pipeline can use this body; Save runs it in the kitchen").stylize(
                "$text-success")])
        save = self.query_one("#save", Button)
        save.disabled, save.label = bool(self.problems), "Save"

    def on_button_pressed(self, event: Button.Pressed) -> None:
        if event.button.id == "save":
            self.action_save()
        else:
            self.dismiss(None)

    def action_save(self) -> None:
        if self.problems or self.query_one("#save", Button).disabled:
            return
        if self.failed is not None:
            self.dismiss(self.failed)  # asked again after seeing the kitchen's problems
            return
        self.query_one("#save", Button).disabled = True
        self._show([Content("running the body in the kitchen …").stylize("$text-accent")])
        self.kitchen_check(self.query_one("#body", TextArea).text.strip())

    @work(thread=True, exclusive=True, exit_on_error=False, group="editor")
    def kitchen_check(self, body: str) -> None:
        # startup: the app opens before the kitchen check and the library (sqlite-utils) load
        from cook2ltl.assembly.edits import edited_body_check

        check = edited_body_check(self.entry, body, self.primitives, self.verbs,
                                  lambda: self.app.services.validator(self.primitives))
        self.post_message(KitchenChecked(body, check))

    def on_kitchen_checked(self, message: KitchenChecked) -> None:
        check = message.check
        if check.validation != CheckStatus.FAILED:
            self.dismiss(Edited(message.body, check))
            return
        self.failed = Edited(message.body, check)
        self._show([Content("✗ the kitchen refused it:").stylize("bold $text-error"),
                    *(shown(f"  {p}").stylize("$text-error") for p in check.problems),
                    Content("Save again keeps it anyway (its check stays failed); or change it.").stylize(
                        "$text-muted")])
        save = self.query_one("#save", Button)
        save.disabled, save.label = False, "Save failing body"

    def on_worker_state_changed(self, event: Worker.StateChanged) -> None:
        if event.state == WorkerState.ERROR:
            self.check()
            self.app.show_error(event.worker.error)

    def _show(self, lines: list[Content]) -> None:
        self.query_one("#problems", Static).update(Content("\n").join(lines))
