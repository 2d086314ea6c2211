"""`cook2ltl parse`: spans and frames of every step, coloured per category, or JSON."""

from __future__ import annotations

import json
import time

import typer
from rich.console import Console
from rich.text import Text

from cook2ltl.domain import ARGUMENT_LABELS, Label, ParsedRecipe
from cook2ltl.cli.inputs import read_recipe

COLOURS = {
    Label.VERB: "bold red",
    Label.WHAT: "green",
    Label.WHERE: "blue",
    Label.HOW: "magenta",
    Label.TIME: "yellow",
    Label.TEMP: "cyan",
}


def parse_command(
    recipe: str = typer.Argument(..., help="Recipe text file, or - for standard input."),
    as_json: bool = typer.Option(False, "--json", help="Print machine-readable JSON."),
) -> None:
    """Split a recipe into steps and parse each into Verb(What, Where, How, Time, Temperature) frames."""
    from cook2ltl.parse import parse_recipe
    from cook2ltl.parse.serialize import recipe_json
    from cook2ltl.settings import load_settings
    from cook2ltl.stack import dependency_parser, span_extractor

    text = read_recipe(recipe)
    spans, dependencies = span_extractor(load_settings()), dependency_parser()
    started = time.perf_counter()
    parsed = parse_recipe(text, spans, dependencies)
    elapsed = time.perf_counter() - started
    if as_json:
        typer.echo(json.dumps(recipe_json(parsed), ensure_ascii=False, indent=2))
    else:
        show(parsed, Console(), elapsed)


def show(parsed: ParsedRecipe, console: Console, elapsed: float) -> None:
    legend = Text("  ").join(Text(label.value, style=COLOURS[label]) for label in Label)
    console.print(legend)
    for step in parsed.steps:
        line = Text(step.sentence.text)
        for span in step.spans:
            line.stylize(COLOURS[span.label], span.start - step.sentence.start, span.end - step.sentence.start)
        console.print(Text(f"{step.index + 1:>3}. ", style="dim") + line)
        for number, frame in enumerate(step.frames):
            call = Text("      ")
            if frame.negated:
                call.append("¬ ", style="bold")
            call.append(frame.name, style=COLOURS[Label.VERB])
            call.append("(")
            call.append_text(Text(", ").join(_arguments(frame)))
            call.append(")")
            if number < len(step.links):
                call.append(f"   {step.links[number].value}", style="dim")
            console.print(call)
    console.print(f"[dim]{len(parsed.steps)} steps parsed in {elapsed:.2f} s[/dim]")


def _arguments(frame) -> list[Text]:
    pieces = []
    for label in ARGUMENT_LABELS:
        for argument in frame.arguments(label):
            piece = Text(argument.span.text, style=COLOURS[label])
            if argument.inferred:
                piece.append("*", style="dim")  # resolved by zero anaphora
            pieces.append(piece)
    return pieces
