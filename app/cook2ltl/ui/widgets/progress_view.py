"""A formula's progress during a rollout: the formula with the atoms met so far marked, what remains, the
verdict after each action, and at the end why it stopped and whether the task's goal holds (for a recipe in the
world model: its problems by step)."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from textual.content import Content
from textual.widgets import Static

from cook2ltl.ui.literal import formula_text, shown, shown_formula, shown_styled

if TYPE_CHECKING:
    from cook2ltl.assembly.trial import Trial
    from cook2ltl.execution.rollout import TraceStep
    from cook2ltl.ltl.ast import Atom, Formula
    from cook2ltl.pipeline.world_rollout import LineRun, RecipeRollout
    from cook2ltl.ui.messages import RecipeRolloutBegan, RolloutBegan

VERDICT_STYLE = {"satisfied": "bold $text-success", "presumably_true": "$text-success",
                 "presumably_false": "$text-warning", "violated": "bold $text-error"}
MET_STYLE = "bold underline $text-success"


def marked(formula: Formula, met: frozenset[Atom]) -> Content:
    """The formula in Unicode with every occurrence of a met atom styled."""
    from cook2ltl.ltl.printer import to_unicode  # startup: the app opens before the LTL printer (lark) loads

    text = formula_text(formula)
    if text is None:
        return shown_formula(formula)
    ranges = []
    for atom in met:
        # Not part of a longer name; an atom without arguments is not an argument of another atom either.
        inside = "" if atom.args else r"(?<!\w\()(?<!, )"
        pattern = rf"(?<!\w){inside}{re.escape(to_unicode(atom))}(?![\w(])"
        ranges += [(match.start(), match.end(), MET_STYLE) for match in re.finditer(pattern, text)]
    return shown_styled(text, ranges)


def verdict_content(value: str) -> Content:
    return Content(value.replace("_", " ")).stylize(VERDICT_STYLE[value])


class FormulaProgress(Static):
    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.header: list[Content] = []
        self.formula: Formula | None = None

    def begin(self, began: RolloutBegan) -> None:
        title = f"task {began.task.id} · “{began.task.instruction}”" if began.task else "formula"
        self.header = [shown(f"{title} · {began.scene}").stylize("bold")]
        if began.plan is not None:
            calls = " · ".join(call.text() for call in began.plan.calls) or "(no admissible plan)"
            self.header.append(_label("plan") + shown(calls) + shown(
                f"  [{began.plan.model}: {', '.join(began.plan.sources)}; {began.plan.seconds:.1f} s]"
            ).stylize("$text-muted"))
        if began.unobservable:
            never = ", ".join(atom.text for atom in began.unobservable)
            self.header.append(shown(f"the kitchen cannot report {never}: never true").stylize("$text-warning"))
        self.formula = began.formula
        self._draw(frozenset(), began.formula, "presumably_false")

    def begin_recipe(self, began: RecipeRolloutBegan) -> None:
        core = began.began
        self.header = [shown(f"{began.title} · {core.steps} steps, {core.actions} actions · the world model"
                               ).stylize("bold")]
        if core.unobservable:
            never = ", ".join(atom.text for atom in core.unobservable)
            self.header.append(shown(f"the world cannot tell {never}: true only once waited for"
                                       ).stylize("$text-warning"))
        self.formula = core.formula
        self._draw(frozenset(), core.formula, "presumably_false")

    def step(self, step: TraceStep | LineRun) -> None:
        """After a kitchen action, or a plan line applied in the world model."""
        self._draw(step.met, step.remaining, step.verdict.value)

    def finish(self, trial: Trial) -> None:
        # startup: the app opens before the trial (pydantic, lark, sqlite-utils) loads
        from cook2ltl.assembly.trial import explain

        result = trial.rollout
        met = result.steps[-1].met if result.steps else frozenset()
        lines = [_label("verdict") + verdict_content(result.verdict.value) + shown(f" — {explain(result)}")]
        if trial.goal is not None:
            for condition, ok in trial.goal.conditions:
                mark = Content("✓ ").stylize("$text-success") if ok else Content("✗ ").stylize("$text-error")
                lines.append(_label("goal") + mark + shown(condition.text()))
        outcome = Content("success").stylize("bold $text-success") if trial.success else \
            Content("failure").stylize("bold $text-error")
        planning = f" · {trial.plan.seconds:.1f} s planning" if trial.plan else ""
        lines.append(outcome + Content(f" · {len(result.steps)} actions · {result.seconds:.2f} s in the kitchen"
                                       f"{planning}").stylize("$text-muted"))
        remaining = result.steps[-1].remaining if result.steps else result.formula
        self._draw(met, remaining, result.verdict.value, lines)

    def finish_recipe(self, rollout: RecipeRollout) -> None:
        lines = [_label("verdict") + verdict_content(rollout.verdict.value)]
        for step in rollout.steps:
            for problem in step.problems:
                lines.append(_label(f"step {step.result.step.index + 1}") + Content("! ").stylize("$text-error")
                             + shown(problem))
        reached = sum(1 for step in rollout.steps if step.reached)
        outcome = Content("success").stylize("bold $text-success") if rollout.success else \
            Content("failure").stylize("bold $text-error")
        lines.append(outcome + Content(f" · {reached} of {len(rollout.steps)} steps reached their effects"
                                       ).stylize("$text-muted"))
        self._draw(rollout.met, rollout.remaining, rollout.verdict.value, lines)

    def _draw(self, met: frozenset[Atom], remaining: Formula, verdict: str, tail: list[Content] = ()) -> None:
        lines = [*self.header, _label("φ") + marked(self.formula, met),
                 _label("remaining") + shown_formula(remaining),
                 _label("now") + verdict_content(verdict), *tail]
        self.update(Content("\n").join(lines))


def _label(text: str) -> Content:
    return Content(f"{text:<10}").stylize("$text-muted")
