"""Each step's formula, in Unicode for people or in Spot's syntax for tools, with the problems found."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.content import Content
from textual.reactive import reactive
from textual.widgets import Static

from cook2ltl.ui.literal import shown, shown_formula

if TYPE_CHECKING:
    from cook2ltl.ltl.ast import Formula
    from cook2ltl.pipeline.records import StepResult


class FormulaList(Static):
    spot: reactive[bool] = reactive(False)

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.steps: list[StepResult] = []
        self.whole: Formula | None = None

    def clear(self) -> None:
        self.steps, self.whole = [], None
        self.update("")

    def add_step(self, result: StepResult) -> None:
        self.steps.append(result)
        self.refresh_formulas()

    def finish(self, whole: Formula) -> None:
        self.whole = whole
        self.refresh_formulas()

    def watch_spot(self) -> None:
        self.refresh_formulas()

    def refresh_formulas(self) -> None:
        syntax = Content(f"syntax: {'Spot' if self.spot else 'Unicode'} (ctrl+l switches)").stylize("$text-muted")
        blocks = [syntax]
        for result in self.steps:
            block = shown(f"{result.step.index + 1:>3}  {result.step.sentence.text}").stylize("bold")
            block += Content("\n     φ = ") + shown_formula(result.formula, self.spot).stylize("$text-warning")
            for problem in result.problems:
                block += Content("\n     ! ").stylize("bold $text-error") + shown(problem)
            blocks.append(block)
        if self.whole is not None:
            blocks.append(Content("whole recipe\n").stylize("bold") + shown_formula(self.whole, self.spot).stylize("$text-warning"))
        self.update(Content("\n\n").join(blocks))
