"""What `translate` and `rollout RECIPE-FILE` share: the translator their options describe, and Algorithm 1 run
on a recipe's text with a progress bar on standard error."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import typer
from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

from cook2ltl.assembly import backends, translators
from cook2ltl.assembly.translators import TranslateOptions
from cook2ltl.domain.actions import PrimitiveSet
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.pipeline.records import ActionDone, Translation, TranslationFinished, TranslationStarted
from cook2ltl.pipeline.translator import Translator, run
from cook2ltl.text_safety import literal, visible


@contextmanager
def open_translator(primitives: PrimitiveSet, model: str, library: Path | None, options: TranslateOptions,
                    errors: Console) -> Iterator[Translator]:
    """The translator of the command's options; its library and kitchen are closed on exit."""
    def notice(text: str) -> None:
        errors.print(literal(text, "yellow"))

    with translators.open_translator(primitives, backends.load_model(model), library, options, notice) as translator:
        yield translator


def translated(text: str, translator: Translator, errors: Console) -> Translation:
    """The recipe parsed and translated, its progress drawn on `errors`; exit 130 if stopped before the end."""
    events = run(text, backends.span_extractor(load_settings()), backends.dependency_parser(), translator)
    columns = (TextColumn("{task.description}", markup=False), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn())
    # Off a terminal the bar draws nothing, not even the blank line a transient bar leaves before an error.
    with Progress(*columns, console=errors, transient=True, disable=not errors.is_terminal) as progress:
        task = progress.add_task("parsing", total=None)
        for event in events:
            if isinstance(event, TranslationStarted):
                progress.update(task, total=event.actions, description="reducing")
            elif isinstance(event, ActionDone):
                reduction = event.result.reduction
                progress.update(task, completed=event.done,
                                description=visible(f"{reduction.action.text()} ({reduction.source.value})"))
            elif isinstance(event, TranslationFinished):
                return event.translation
    raise typer.Exit(130)  # stopped before the end
