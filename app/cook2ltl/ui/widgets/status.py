"""The status line of a screen's long work: the latest progress text and, when the total is known, a bar."""

from __future__ import annotations

from textual.app import ComposeResult
from textual.containers import Horizontal
from textual.widgets import Label, ProgressBar

from cook2ltl.ui.literal import shown


class WorkStatus(Horizontal):
    def compose(self) -> ComposeResult:
        yield Label("ready", id="status-text")
        yield ProgressBar(show_eta=False, id="status-bar")

    def on_mount(self) -> None:
        self.query_one(ProgressBar).display = False  # until a job reports a total

    def show(self, text: str, done: int | None = None, total: int | None = None) -> None:
        self.query_one("#status-text", Label).update(shown(text))
        bar = self.query_one(ProgressBar)
        bar.display = total is not None and total > 0
        if bar.display:
            bar.update(total=total, progress=done or 0)
