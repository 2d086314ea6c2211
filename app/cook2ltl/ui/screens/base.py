"""What every working screen shares: one thread worker at a time, its progress in the status line, ctrl+g to
cancel it (a `threading.Event` the core checks between steps), and failures shown as a dialog."""

from __future__ import annotations

import threading

from textual.binding import Binding
from textual.reactive import reactive
from textual.screen import Screen
from textual.worker import Worker, WorkerState

from cook2ltl.ui.messages import WorkNotice, WorkProgress, WorkStopped
from cook2ltl.ui.widgets.status import WorkStatus


class WorkScreen(Screen):
    BINDINGS = [Binding("ctrl+g", "cancel", "Cancel", id="cancel")]
    PALETTE: tuple[tuple[str, str, str], ...] = ()  # (title, help, action) for the command palette
    JOB = ""  # the worker group of the screen's jobs (started with `begin`); other workers only read

    busy: reactive[bool] = reactive(False, bindings=True)

    def __init__(self) -> None:
        super().__init__()
        self.cancel_event = threading.Event()

    def begin(self, what: str) -> threading.Event:
        """Mark the screen busy and give the new job its own cancel event."""
        self.cancel_event = threading.Event()
        self.busy = True
        self.query_one(WorkStatus).show(what)
        return self.cancel_event

    def action_cancel(self) -> None:
        if self.busy:
            self.cancel_event.set()
            self.query_one(WorkStatus).show("stopping after the current step …")

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        if action == "cancel":
            return self.busy  # in the footer only while something runs
        return True

    def on_work_progress(self, message: WorkProgress) -> None:
        self.query_one(WorkStatus).show(message.text, message.done, message.total)

    def on_work_notice(self, message: WorkNotice) -> None:
        self.notify(message.text, severity="warning", timeout=10)

    def on_work_stopped(self, _: WorkStopped) -> None:
        self.query_one(WorkStatus).show("stopped")

    def on_worker_state_changed(self, event: Worker.StateChanged) -> None:
        if event.state not in (WorkerState.SUCCESS, WorkerState.ERROR, WorkerState.CANCELLED):
            return
        job = event.worker.group == self.JOB
        if event.state == WorkerState.ERROR:
            if job:
                self.query_one(WorkStatus).show("failed")
            self.app.show_error(event.worker.error)
        if job:
            self.busy = False
            self.work_ended()

    def work_ended(self) -> None:
        """After any job, whatever its end: re-enable what `busy` disabled."""

    def on_unmount(self) -> None:
        self.cancel_event.set()  # a thread still running stops at its next check
