"""A parsed recipe: each step with its spans coloured by category, and under it the frames built from them."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.content import Content
from textual.widgets import Static

from cook2ltl.domain.recipe import ARGUMENT_LABELS
from cook2ltl.ui.literal import shown, shown_styled

if TYPE_CHECKING:
    from cook2ltl.domain.recipe import Frame, ParsedRecipe, Step

# Theme variables, so every theme colours the six categories of the paper's Sec. IV-C.
LABEL_STYLE = {
    "VERB": "bold $text-accent",
    "WHAT": "underline $text-primary",
    "WHERE": "underline $text-success",
    "HOW": "underline $text-secondary",
    "TIME": "italic $text-warning",
    "TEMP": "italic $text-error",
}
LINK_WORD = {"and": " then ", "or": " or "}


def legend() -> Content:
    parts = [Content(label.lower()).stylize(style) for label, style in LABEL_STYLE.items()]
    return (Content("categories: ").stylize("$text-muted") + Content("  ").join(parts)
            + Content("   * an object inferred from context").stylize("$text-muted"))


def step_content(step: Step) -> Content:
    start = step.sentence.start
    sentence = shown_styled(step.sentence.text, [(span.start - start, span.end - start, LABEL_STYLE[span.label.value])
                                                 for span in step.spans])
    text = Content(f"{step.index + 1:>3}  ").stylize("$text-muted") + sentence
    frames = [frame_content(frame) for frame in step.frames]
    if frames:
        joined = frames[0]
        for link, frame in zip(step.links, frames[1:]):
            joined += Content(LINK_WORD[link.value]).stylize("$text-muted") + frame
        text += Content("\n     ") + joined
    else:
        text += Content("\n     no action found").stylize("$text-warning")
    return text


def frame_content(frame: Frame) -> Content:
    """verb(what, where, …) with each argument in its category's style; * marks one zero anaphora inferred."""
    arguments = [shown(argument.span.text + ("*" if argument.inferred else "")).stylize(LABEL_STYLE[label.value])
                 for label in ARGUMENT_LABELS for argument in frame.arguments(label)]
    call = shown(frame.name).stylize(LABEL_STYLE["VERB"]) + Content("(") + Content(", ").join(arguments) + Content(")")
    return Content("not ").stylize("bold $text-error") + call if frame.negated else call


class StepsView(Static):
    """Blank until a recipe is parsed."""

    def show_recipe(self, parsed: ParsedRecipe) -> None:
        steps = [step_content(step) for step in parsed.steps] or [Content("no steps found in the recipe")]
        self.update(Content("\n\n").join([legend(), *steps]))
