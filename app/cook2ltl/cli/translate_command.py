"""`cook2ltl translate`: per step the frames, their reductions (primitive, library or new) and the formula."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Optional

import typer
from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.text import Text

from cook2ltl.cli.inputs import read_recipe
from cook2ltl.pipeline import ActionDone, Finished, Started, Translation, Variant
from cook2ltl.reduce.llm import DEFAULT_MODEL
from cook2ltl.reduce.model import Source

SOURCE_STYLE = {Source.PRIMITIVE: "green", Source.LIBRARY: "cyan", Source.LLM: "magenta"}


def translate_command(
    recipe: str = typer.Argument(..., help="Recipe text file, or - for standard input."),
    primitives: str = typer.Option("recipe", "--primitives", help="recipe, ai2thor, or a TOML file of your robot's set."),
    variant: Variant = typer.Option(Variant.AR_LIBRARY, "--variant", case_sensitive=False,
                                    help="AR* reduces every action; AR passes primitives through; "
                                         "AR+A also reuses and grows the action library."),
    library: Optional[Path] = typer.Option(None, "--library", help="Action library file (default: $COOK2LTL_LIBRARY, "
                                           "else library.sqlite in the user data folder)."),
    model: str = typer.Option(DEFAULT_MODEL, "--model", help="Language model of the manifest (`cook2ltl models`)."),
    max_lines: int = typer.Option(12, "--max-lines", min=1, max=40, help="Most lines one reduction may have."),
    comments: bool = typer.Option(False, "--comments/--no-comments",
                                  help="Let the model comment each line, as the paper's prompt does (about 2x slower)."),
    as_json: bool = typer.Option(False, "--json", help="Print machine-readable JSON."),
) -> None:
    """Translate a recipe into LTL formulas over the robot's primitive actions (the paper's Algorithm 1)."""
    from cook2ltl import paths
    from cook2ltl.library import Library
    from cook2ltl.pipeline import Translator, run
    from cook2ltl.reduce.llm import load_model
    from cook2ltl.reduce.primitives import load_primitives
    from cook2ltl.reduce.reduction import ReductionSettings
    from cook2ltl.settings import load_settings
    from cook2ltl.stack import dependency_parser, span_extractor
    from cook2ltl.translate.serialize import translation_json

    text = read_recipe(recipe)
    chosen = load_primitives(primitives)
    language_model = load_model(model)
    store = Library(library or paths.library_file()) if variant == Variant.AR_LIBRARY else None
    translator = Translator(chosen, language_model, store, variant, ReductionSettings(max_lines, comments))
    errors = Console(stderr=True)
    try:
        events = run(text, span_extractor(load_settings()), dependency_parser(), translator)
        translation = _follow(events, errors)
    finally:
        if store is not None:
            store.close()
    if as_json:
        typer.echo(json.dumps(translation_json(translation), ensure_ascii=False, indent=2))
    else:
        show(translation, Console())


def _follow(events, console: Console) -> Translation:
    columns = (TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn())
    with Progress(*columns, console=console, transient=True) as progress:
        task = progress.add_task("parsing", total=None)
        for event in events:
            if isinstance(event, Started):
                progress.update(task, total=event.actions, description="reducing")
            elif isinstance(event, ActionDone):
                reduction = event.result.reduction
                progress.update(task, completed=event.done,
                                description=f"{reduction.action.text()} [dim]({reduction.source.value})[/dim]")
            elif isinstance(event, Finished):
                return event.translation
    raise typer.Exit(130)  # stopped before the end


def show(translation: Translation, console: Console) -> None:
    from cook2ltl.ltl.printer import to_spot, to_unicode

    console.print(f"[dim]primitives {translation.primitives} · variant {translation.variant.value} · "
                  f"model {translation.model}[/dim]")
    for step in translation.steps:
        console.print(Text(f"{step.step.index + 1:>3}. ", style="dim") + Text(step.step.sentence.text))
        for index, frame in enumerate(step.step.frames):
            console.print(Text("      " + frame.signature(), style="dim"))
            for result in (r for r in step.actions if r.frame_index == index):
                _show_reduction(result.reduction, console)
        console.print(Text("      φ = ", style="dim") + Text(to_unicode(step.formula), style="yellow"), soft_wrap=True)
        console.print(Text("          " + to_spot(step.formula), style="dim"), soft_wrap=True)
        for problem in step.problems:
            console.print(f"      [bold red]![/bold red] {problem}", highlight=False)
    stats = translation.stats
    console.print(
        f"[dim]{stats.actions} actions: {stats.primitive} primitive, {stats.library_hits} from the library, "
        f"{stats.llm_calls} LLM calls ({stats.prompt_tokens} prompt + {stats.completion_tokens} completion tokens, "
        f"{stats.llm_seconds:.1f} s); {stats.new_entries} new library entries; {stats.seconds:.1f} s in all[/dim]"
    )


def _show_reduction(reduction, console: Console) -> None:
    line = Text("        → ")
    line.append(reduction.action.text(), style="bold")
    entry = f" #{reduction.entry_id}" if reduction.entry_id is not None else ""
    line.append(f"  {reduction.source.value}{entry}", style=SOURCE_STYLE[reduction.source])
    console.print(line)
    if reduction.source != Source.PRIMITIVE:
        for call in reduction.body:
            console.print(f"            {call.text()}", highlight=False)
    for dropped in reduction.dropped:
        console.print(f"            [red]✗ {dropped}[/red] [dim](not admissible, dropped)[/dim]", highlight=False)
