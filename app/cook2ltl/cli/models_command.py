"""`cook2ltl models`: the manifest and each model's state; provisioning; NER validation."""

from __future__ import annotations

import json
import time
from dataclasses import replace
from pathlib import Path
from typing import Optional

import typer
from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from cook2ltl import paths
from cook2ltl.assembly import backends
from cook2ltl.assembly.manifest import ModelState, load_manifest, state_of
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.text_safety import literal, styled, terminal, visible

models_app = typer.Typer(help="List, provision and evaluate the models.", invoke_without_command=True, no_args_is_help=False)
STATE_STYLE = {ModelState.READY: "green", ModelState.MISSING: "yellow", ModelState.CORRUPT: "bold red"}


@models_app.callback()
def list_models(context: typer.Context) -> None:
    """Each model of models/models.toml: where it comes from, its licence and its state."""
    if context.invoked_subcommand:
        return
    table = Table("model", "state", "from", "licence")
    for entry in load_manifest().values():
        state = state_of(entry)
        table.add_row(styled(entry.name, "\n", (entry.role, "dim")), literal(state.value, STATE_STYLE[state]),
                      styled(entry.origin(), "\n", (entry.upstream, "dim")), literal(entry.licence))
    console = terminal()
    console.print(table)
    console.print(literal(f"weights: {paths.model_cache_dir()}  ·  `cook2ltl models provision` fetches or trains "
                          "the rest", "dim"))


@models_app.command("provision")
def provision_command(
    names: Optional[list[str]] = typer.Argument(None, help="Only these models (default: all)."),
    force: bool = typer.Option(False, help="Fetch or train again even if present."),
) -> None:
    """Fetch or train what is missing into the per-user cache, and link it under models/."""
    # startup: `cook2ltl --help` imports this module; provisioning loads when the command runs
    from cook2ltl.assembly.provision import provision

    manifest = load_manifest()
    unknown = set(names or []) - set(manifest)
    if unknown:
        raise typer.BadParameter(f"unknown model(s): {', '.join(sorted(unknown))}; known: {', '.join(manifest)}")
    chosen = [entry for name, entry in manifest.items() if not names or name in names]
    console = terminal(stderr=True)
    events = provision(chosen, force=force)
    if console.is_terminal:
        _show_live(events, console)
    else:
        _show_milestones(events, console)


def _show_live(events, console: Console) -> None:
    columns = (TextColumn("{task.fields[model]:<20}", markup=False), BarColumn(), MofNCompleteColumn(),
               TimeElapsedColumn(), TextColumn("{task.description}", markup=False))
    with Progress(*columns, console=console) as progress:
        tasks = {}
        for event in events:
            if event.model not in tasks:
                tasks[event.model] = progress.add_task(visible(event.message), model=visible(event.model), total=None)
            total = 1 if event.finished else event.total or None
            done = 1 if event.finished else event.done
            progress.update(tasks[event.model], description=visible(event.message), total=total, completed=done)


def _show_milestones(events, console: Console) -> None:
    """In a log (CI, make without a terminal) a line per tenth of the work, not a redrawn bar."""
    started, shown = time.perf_counter(), {}
    for event in events:
        tenth = 10 * event.done // event.total if event.total else -1
        if event.finished or shown.get(event.model) != tenth:
            shown[event.model] = tenth
            progress = f" {event.done}/{event.total}" if event.total else ""
            console.print(f"[{time.perf_counter() - started:6.0f} s] {event.model}: {event.message}{progress}",
                          highlight=False)


@models_app.command("eval-ner")
def eval_ner_command(
    checkpoint: Optional[Path] = typer.Option(None, help="A GLiNER checkpoint folder (default: the configured one)."),
    as_json: bool = typer.Option(False, "--json"),
) -> None:
    """Strict span micro-F1 on the held-out recipes, overall and per label."""
    # startup: `cook2ltl --help` imports this module; the training code loads when the command runs
    from cook2ltl.parse.training.validate import validate

    settings = load_settings()
    if checkpoint:
        settings = replace(settings, ner=replace(settings.ner, checkpoint=paths.user_path(checkpoint, "--checkpoint")))
    data = paths.models_dir() / load_manifest()[backends.SPAN_MODEL].data
    report = validate(backends.span_extractor(settings), data)
    rows = {"overall": report.overall, **{label.value: score for label, score in report.per_label.items()}}
    if as_json:
        typer.echo(json.dumps({name: {"f1": round(s.f1, 4), "precision": round(s.precision, 4),
                                      "recall": round(s.recall, 4), "gold": s.gold, "predicted": s.predicted}
                               for name, s in rows.items()} | {"sentences": report.sentences}, indent=2))
        return
    table = Table("label", "F1", "precision", "recall", "gold", "predicted",
                  title=f"Strict span scores on {report.sentences} held-out sentences")
    for name, score in rows.items():
        table.add_row(name, f"{score.f1:.3f}", f"{score.precision:.3f}", f"{score.recall:.3f}",
                      str(score.gold), str(score.predicted))
    terminal().print(table)
