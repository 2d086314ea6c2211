"""The reductions of a translation as a table, one row per action in the pipeline's order: pending until
reduced, then primitive, cached (found in the library) or new (written by the model now), with its plan."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.content import Content
from textual.widgets import DataTable

if TYPE_CHECKING:
    from cook2ltl.domain import ParsedRecipe
    from cook2ltl.pipeline import ActionResult, Stats

COLUMNS = ("#", "step", "action", "reduction", "LLM s", "plan")  # the plan last: it is the long one


class ReductionsTable(DataTable):
    def on_mount(self) -> None:
        for name in COLUMNS:
            self.add_column(name, key=name)
        self.cursor_type = "row"

    def show_pending(self, parsed: ParsedRecipe) -> None:
        """One row per action, in the order the pipeline reduces them."""
        from cook2ltl.reduce.action import actions_of

        self.clear()
        number = 0
        for step in parsed.steps:
            for frame in step.frames:
                for action in actions_of(frame):
                    number += 1
                    self.add_row(str(number), str(step.index + 1), action.text(), _muted("pending"), "", "",
                                 key=str(number))
        self._mark_working(1)

    def show_result(self, number: int, result: ActionResult) -> None:
        key = str(number)
        if key not in self.rows:
            return
        reduction = result.reduction
        plan = " · ".join(call.text() for call in (result.plan or reduction.body))
        if reduction.dropped:
            plan += f"  (✗ {len(reduction.dropped)} dropped)"
        seconds = f"{reduction.usage.seconds:.1f}" if reduction.source.value == "llm" else ""
        self.update_cell(key, "reduction", reduction_label(result))
        self.update_cell(key, "LLM s", seconds)
        self.update_cell(key, "plan", plan, update_width=True)
        self._mark_working(number + 1)

    def _mark_working(self, number: int) -> None:
        if str(number) in self.rows:
            self.update_cell(str(number), "reduction", Content("reducing …").stylize("$text-accent"), update_width=True)


def reduction_label(result: ActionResult) -> Content:
    reduction = result.reduction
    entry = f" #{reduction.entry_id}" if reduction.entry_id is not None else ""
    if not result.plan:
        return Content("no plan").stylize("$text-error")
    if reduction.source.value == "primitive":
        return _muted("primitive")
    if reduction.source.value == "library":
        return Content(f"cached{entry}").stylize("$text-success")
    return Content(f"new{entry}").stylize("$text-warning")


def summary(stats: Stats) -> str:
    return (f"{stats.actions} actions: {stats.primitive} primitive, {stats.library_hits} cached, "
            f"{stats.llm_calls} by the model ({stats.llm_seconds:.1f} s LLM time, {stats.new_entries} new library "
            f"entries pending review); {stats.seconds:.1f} s in all")


def _muted(text: str) -> Content:
    return Content(text).stylize("$text-muted")
