"""`cook2ltl parse`: spans and frames of every step, coloured per category, or JSON."""

from __future__ import annotations

import time

import typer
from rich.console import Console
from rich.text import Text

from cook2ltl.assembly import backends
from cook2ltl.domain.recipe import ARGUMENT_LABELS, Label, ParsedRecipe
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.parse import parse_recipe
from cook2ltl.parse.serialize import recipe_json
from cook2ltl.preprocess.recipe_file import read_recipe
from cook2ltl.text_safety import json_text, literal, styled, terminal

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
    text = read_recipe(recipe)
    spans, dependencies = backends.span_extractor(load_settings()), backends.dependency_parser()
    started = time.perf_counter()
    parsed = parse_recipe(text, spans, dependencies)
    elapsed = time.perf_counter() - started
    if as_json:
        typer.echo(json_text(recipe_json(parsed)))
    else:
        show(parsed, terminal(), elapsed)


def show(parsed: ParsedRecipe, console: Console, elapsed: float) -> None:
    legend = Text("  ").join(literal(label.value, style=COLOURS[label]) for label in Label)
    console.print(legend)
    for step in parsed.steps:
        line = Text(step.sentence.text)  # styled by the spans' offsets into the text, then shown literally
        for span in step.spans:
            line.stylize(COLOURS[span.label], span.start - step.sentence.start, span.end - step.sentence.start)
        console.print(styled((f"{step.index + 1:>3}. ", "dim"), line))
        for number, frame in enumerate(step.frames):
            link = f"   {step.links[number].value}" if number < len(step.links) else ""
            console.print(styled("      ", ("¬ " if frame.negated else "", "bold"), (frame.name, COLOURS[Label.VERB]),
                                 "(", Text(", ").join(_arguments(frame)), ")", (link, "dim")))
    console.print(literal(f"{len(parsed.steps)} steps parsed in {elapsed:.2f} s", "dim"))


def _arguments(frame) -> list[Text]:
    pieces = []
    for label in ARGUMENT_LABELS:
        for argument in frame.arguments(label):
            piece = literal(argument.span.text, style=COLOURS[label])
            if argument.inferred:
                piece.append("*", style="dim")  # resolved by zero anaphora
            pieces.append(piece)
    return pieces
