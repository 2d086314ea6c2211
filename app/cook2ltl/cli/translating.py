"""What `translate` and `rollout RECIPE-FILE` share: the translator their options describe, and Algorithm 1 run
on a recipe's text with a progress bar on standard error."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import typer
from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

from cook2ltl.pipeline import ActionDone, Finished, Started, Translation, Translator, Variant
from cook2ltl.reduce.model import PrimitiveSet
from cook2ltl.reduce.reduction import ReductionSettings
from cook2ltl.text_safety import literal, visible


@contextmanager
def open_translator(primitives: PrimitiveSet, model: str, library: Path | None, variant: Variant,
                    settings: ReductionSettings, validate: bool | None, repairs: int | None, approved_only: bool,
                    ground: bool, errors: Console) -> Iterator[Translator]:
    """The translator of the command's options; its library and kitchen validator are closed on exit.
    `repairs` None: the settings' [translate] repairs."""
    from cook2ltl import paths
    from cook2ltl.library import Library
    from cook2ltl.reduce.llm import load_model
    from cook2ltl.settings import load_settings

    language_model = load_model(model)
    grounding = _grounding(primitives, ground)
    validator = _validator(primitives, validate, variant, errors, grounding is not None)
    store = Library(library or paths.library_file()) if variant == Variant.AR_LIBRARY else None
    try:
        yield Translator(primitives, language_model, store, variant, settings, validator,
                         load_settings().translate.repairs if repairs is None else repairs, approved_only, grounding)
    finally:
        if store is not None:
            store.close()
        if validator is not None:
            validator.close()


def translated(text: str, translator: Translator, errors: Console) -> Translation:
    """The recipe parsed and translated, its progress drawn on `errors`; exit 130 if stopped before the end."""
    from cook2ltl.pipeline import run
    from cook2ltl.settings import load_settings
    from cook2ltl.stack import dependency_parser, span_extractor

    events = run(text, span_extractor(load_settings()), dependency_parser(), translator)
    columns = (TextColumn("{task.description}", markup=False), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn())
    # Off a terminal the bar draws nothing, not even the blank line a transient bar leaves before an error.
    with Progress(*columns, console=errors, transient=True, disable=not errors.is_terminal) as progress:
        task = progress.add_task("parsing", total=None)
        for event in events:
            if isinstance(event, Started):
                progress.update(task, total=event.actions, description="reducing")
            elif isinstance(event, ActionDone):
                reduction = event.result.reduction
                progress.update(task, completed=event.done,
                                description=visible(f"{reduction.action.text()} ({reduction.source.value})"))
            elif isinstance(event, Finished):
                return event.translation
    raise typer.Exit(130)  # stopped before the end


def _grounding(primitives: PrimitiveSet, ground: bool):
    """The set's world model with the planner, or None: turned off, or the set names no world."""
    from cook2ltl.world.kitchens import grounding

    return grounding(primitives) if ground else None


def _validator(primitives: PrimitiveSet, validate: bool | None, variant: Variant, errors: Console,
               grounded: bool = False):
    """The kitchen validator, or None: not asked for, or by default with a primitive set it cannot run (asked
    for explicitly, that is an error). A set whose world has its own kitchen file is judged there, not by
    THOR stand-ins, unless asked for."""
    from cook2ltl.reduce.validation import KitchenValidator, unsupported

    if validate is False or (validate is None and variant != Variant.AR_LIBRARY):
        return None
    if validate is None and grounded and primitives.world.kitchen is not None:
        return None
    missing = unsupported(primitives)
    if missing and validate is None:
        errors.print(literal(f"not validating: the kitchen has no action for {', '.join(missing)}", "yellow"))
        return None
    return KitchenValidator(primitives)
