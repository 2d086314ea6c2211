"""What every working screen shares: one thread worker at a time, its progress in the status line, ctrl+g to
cancel it (the worker hands its own `cancelled_event` to the core, which checks it between steps), and failures
shown as a dialog."""

from __future__ import annotations

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

    def begin(self, what: str) -> None:
        """Mark the screen busy before its job's worker starts."""
        self.busy = True
        self.query_one(WorkStatus).show(what)

    def action_cancel(self) -> None:
        if self.busy:
            self._stop_jobs()
            self.query_one(WorkStatus).show("stopping after the current step …")

    def _stop_jobs(self) -> None:
        # The worker's own event, not Worker.cancel(): the thread ends after its current step as at the end of a
        # run, so the screen is not free for the next job while the thread still holds the models.
        for worker in self.workers:
            if worker.node is self and worker.group == self.JOB and not worker.is_finished:
                worker.cancelled_event.set()

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
        self._stop_jobs()  # a thread still running stops at its next check
