"""The reductions of a translation as a table, one row per action in the pipeline's order: pending until
reduced, then primitive, cached (found in the library), reused (a library entry learnt for a verb the table reads
as the same action, or for another signature) or new (written by the model now, with its time and its kitchen
check), with its plan; and the chosen row in full below it, a reuse with where it came from and why."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.content import Content
from textual.widgets import DataTable

from cook2ltl.text_safety import literal
from cook2ltl.ui.literal import shown
from cook2ltl.ui.widgets.entry_detail import check_content

if TYPE_CHECKING:
    from cook2ltl.domain.recipe import ParsedRecipe
    from cook2ltl.pipeline.records import ActionResult, Stats, Translation

# (name, width): Textual content cells are not measured by the table, so theirs are fixed.
COLUMNS = (("#", None), ("step", None), ("action", None), ("reduction", 14), ("LLM s", None), ("kitchen", 9),
           ("plan", None))


class ReductionsTable(DataTable):
    def __init__(self, **kwargs) -> None:
        super().__init__(cursor_type="row", **kwargs)
        self.results: dict[str, ActionResult] = {}

    def on_mount(self) -> None:
        for name, width in COLUMNS:
            self.add_column(name, key=name, width=width)

    def show_pending(self, parsed: ParsedRecipe) -> None:
        """One row per action, in the order the pipeline reduces them."""
        from cook2ltl.reduce.action import actions_of  # startup: the app opens before reduce.action (~1 ms) loads

        self.clear()
        self.results = {}
        number = 0
        for step in parsed.steps:
            for frame in step.frames:
                for action in actions_of(frame):
                    number += 1
                    self.add_row(str(number), str(step.index + 1), literal(action.text()), _muted("pending"), "",
                                 "", literal(""), key=str(number))
        self._mark_working(1)

    def show_result(self, number: int, result: ActionResult) -> None:
        key = str(number)
        if key not in self.rows:
            return
        self.results[key] = result
        reduction = result.reduction
        plan = " · ".join(call.text() for call in (result.plan or reduction.body))
        seconds = sum(r.usage.seconds for r in (*result.attempts, reduction)) if reduction.source.value == "llm" else None
        self.update_cell(key, "reduction", reduction_label(result))
        self.update_cell(key, "LLM s", f"{seconds:.1f}" if seconds is not None else "", update_width=True)
        self.update_cell(key, "kitchen", check_content(result.validation.status) if result.validation else "")
        self.update_cell(key, "plan", literal(plan), update_width=True)
        self._mark_working(number + 1)

    def highlighted(self) -> ActionResult | None:
        if not self.row_count:
            return None
        return self.results.get(self.coordinate_to_cell_key(self.cursor_coordinate).row_key.value)

    def _mark_working(self, number: int) -> None:
        if str(number) in self.rows:
            self.update_cell(str(number), "reduction", Content("reducing …").stylize("$text-accent"))


def reduction_label(result: ActionResult) -> Content:
    reduction = result.reduction
    entry = f" #{reduction.entry_id}" if reduction.entry_id is not None else ""
    if not result.plan:
        return Content("no plan").stylize("$text-error")
    if reduction.source.value == "primitive":
        return _muted("primitive")
    if reduction.source.value == "library":
        return Content(f"{'reused' if result.reuse else 'cached'}{entry}").stylize("$text-success")
    repairs = f" +{len(result.attempts)} rep." if result.attempts else ""
    return Content(f"new{entry}{repairs}").stylize("$text-warning")


def result_detail(result: ActionResult | None) -> Content:
    """Everything about one reduction: the plan line by line, dropped lines, the kitchen check, repairs."""
    if result is None:
        return Content("")
    reduction = result.reduction
    lines = [shown(reduction.action.text()).stylize("bold") + shown(f" · {reduction.source.value}")]
    if result.reuse is not None:
        lines.append(shown(f"reused {result.reuse.text()}").stylize("$text-success"))
    lines += [shown(f"  {call.text()}") for call in result.plan or reduction.body]
    lines += [shown(f"  ✗ {line} (not admissible, dropped)").stylize("$text-error") for line in reduction.dropped]
    check = result.validation
    if check is not None:
        lines.append(Content("kitchen check ") + check_content(check.status) + shown(f" in {check.scene or '—'}"))
        lines += [shown(f"  ! {message}").stylize("$text-error") for message in check.messages()]
    for number, attempt in enumerate(result.attempts, start=1):
        lines.append(_muted(f"attempt {number} (failed the check): {' · '.join(c.text() for c in attempt.body)}"))
    return Content("\n").join(lines)


def summary(translation: Translation) -> Content:
    """The translation's counts and rates, after why any library verbs were not offered to the model."""
    from cook2ltl.pipeline.report import rates_line  # startup: the app opens before the text report (lark) loads

    stats: Stats = translation.stats
    skipped = [shown(f"! {reason}").stylize("$text-warning") for reason in translation.skipped_verbs]
    return Content("\n").join([*skipped, shown(
        f"{stats.actions} actions: {stats.primitive} primitive, {stats.library_hits} cached"
        f"{f' ({stats.cross_reuses} reused across verbs or signatures)' if stats.cross_reuses else ''}, "
        f"{stats.llm_calls} by the model ({stats.llm_seconds:.1f} s LLM time, {stats.new_entries} new library "
        f"entries pending review); {stats.seconds:.1f} s in all\n{rates_line(translation)}")])


def _muted(text: str) -> Content:
    return shown(text).stylize("$text-muted")
