"""Small modal dialogs: an error with its hint, a question to confirm, and a path to open or write."""

from __future__ import annotations

from pathlib import Path

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.screen import ModalScreen
from textual.widgets import Button, Input, Label, Static

from cook2ltl.ui.literal import shown


class ErrorDialog(ModalScreen[None]):
    """What went wrong and what to do about it; never a traceback."""

    BINDINGS = [Binding("escape,enter", "dismiss", "Close", id="dialog.close")]

    def __init__(self, title: str, message: str, hint: str = "") -> None:
        super().__init__(classes="dialog")
        self.title_text, self.message, self.hint = title, message, hint

    def compose(self) -> ComposeResult:
        with Vertical(id="error-dialog", classes="dialog-box"):
            yield Label(shown(self.title_text), classes="dialog-title")
            yield Static(shown(self.message), id="error-message")
            if self.hint:
                yield Static(shown(self.hint), id="error-hint")
            with Horizontal(classes="dialog-buttons"):
                yield Button("OK", variant="primary", id="ok")

    def on_button_pressed(self) -> None:
        self.dismiss()


class ConfirmDialog(ModalScreen[bool]):
    """A yes/no question about something risky; dismissed with True only when confirmed."""

    BINDINGS = [Binding("escape", "dismiss(False)", "Cancel", id="dialog.cancel")]

    def __init__(self, title: str, details: str, question: str, action: str) -> None:
        super().__init__(classes="dialog")
        self.title_text, self.details, self.question, self.action = title, details, question, action

    def compose(self) -> ComposeResult:
        with Vertical(id="confirm-dialog", classes="dialog-box"):
            yield Label(shown(self.title_text), classes="dialog-title")
            yield Static(shown(self.details), id="confirm-details")
            yield Static(shown(self.question), id="confirm-question")
            with Horizontal(classes="dialog-buttons"):
                yield Button(self.action, variant="warning", id="confirm")
                yield Button("Cancel", variant="primary", id="cancel")

    def on_button_pressed(self, event: Button.Pressed) -> None:
        self.dismiss(event.button.id == "confirm")


class PathDialog(ModalScreen[Path | None]):
    """Asks for a file path; dismissed with the path, or None when cancelled."""

    BINDINGS = [Binding("escape", "dismiss(None)", "Cancel", id="dialog.cancel")]

    def __init__(self, title: str, value: str, action: str) -> None:
        super().__init__(classes="dialog")
        self.title_text, self.value, self.action = title, value, action

    def compose(self) -> ComposeResult:
        with Vertical(classes="dialog-box"):
            yield Label(shown(self.title_text), classes="dialog-title")
            yield Input(self.value, id="path")
            with Horizontal(classes="dialog-buttons"):
                yield Button(self.action, variant="primary", id="confirm")
                yield Button("Cancel", id="cancel")

    def on_input_submitted(self) -> None:
        self._confirm()

    def on_button_pressed(self, event: Button.Pressed) -> None:
        if event.button.id == "confirm":
            self._confirm()
        else:
            self.dismiss(None)

    def _confirm(self) -> None:
        text = self.query_one("#path", Input).value.strip()
        self.dismiss(Path(text).expanduser() if text else None)
