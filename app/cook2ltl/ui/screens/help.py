"""The help screen: what each screen is for, and every key binding, read from the bindings themselves."""

from __future__ import annotations

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import VerticalScroll
from textual.content import Content
from textual.screen import ModalScreen
from textual.widgets import Static

from cook2ltl.ui.literal import shown

GUIDE = (
    ("cook2ltl", "turns recipes into robot task specifications in LTL, offline: parse → reduce → action library "
                 "→ LTL → kitchen (the paper's Algorithm 1)."),
    ("Translate", "paste a recipe or open a file, then run. Spans are coloured by category and each step's frames "
                  "are shown under it; every action's reduction says whether it was a primitive, cached in the "
                  "action library or new (written by the language model, with its time); each step gets its "
                  "formula, in Unicode or Spot's syntax, and the whole can be exported as JSON or text."),
    ("Library", "the action library: search it, read an entry's body, provenance and history; approve, reject or "
                "edit it (an edited body is checked as you type)."),
    ("Rollout", "run a kitchen task, the current recipe's formulas or a formula of your own in the embedded "
                "AI2-THOR kitchen, and follow the formula's progress action by action up to the verdict."),
    ("Long work", "loading models, model calls and rollouts run in the background; the status line shows their "
                  "progress and ctrl+g cancels them after the current step."),
)


class HelpScreen(ModalScreen[None]):
    BINDINGS = [Binding("escape,f1,q", "dismiss", "Close", id="help.close")]

    def __init__(self, sections: list[tuple[str, list[Binding]]]) -> None:
        super().__init__(classes="dialog")
        self.sections = sections

    def compose(self) -> ComposeResult:
        with VerticalScroll(id="help", classes="dialog-box"):
            yield Static(Content("\n").join(_paragraph(title, text) for title, text in GUIDE), id="help-guide")
            yield Static(self._keys(), id="help-keys")

    def _keys(self) -> Content:
        lines = []
        for title, bindings in self.sections:
            lines.append(Content(f"\n{title}").stylize("bold $text-primary"))
            for binding in bindings:
                if binding.description:
                    keys = ", ".join(key.strip() for key in binding.key.split(","))
                    lines.append(shown(f"  {keys:<12}").stylize("bold $text-accent") + Content(binding.description))
        return Content("\n").join(lines)


def _paragraph(title: str, text: str) -> Content:
    return Content(title).stylize("bold") + Content(f": {text}\n")
