"""The command line: `cook2ltl` alone (or `cook2ltl app`) opens the app; `parse | translate | rollout | library |
ltl | models | doctor` are headless."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Optional

import typer
from rich.console import Console
from rich.markup import escape

from cook2ltl.cli.bench_command import bench_command
from cook2ltl.cli.library_command import library_app
from cook2ltl.cli.models_command import models_app
from cook2ltl.cli.parse_command import parse_command
from cook2ltl.cli.rollout_command import rollout_command
from cook2ltl.cli.translate_command import translate_command
from cook2ltl.errors import UserError, require_utf8
from cook2ltl.ltl.cli import ltl_app

app = typer.Typer(help="Cooking recipes to LTL task specifications, offline. Without a command: the app.",
                  pretty_exceptions_enable=False)
app.command("parse")(parse_command)
app.command("translate")(translate_command)
app.command("rollout")(rollout_command)
app.command("bench")(bench_command)
app.add_typer(library_app, name="library")
app.add_typer(models_app, name="models")
app.add_typer(ltl_app, name="ltl")


@app.callback(invoke_without_command=True)
def open_app_by_default(context: typer.Context) -> None:
    if context.invoked_subcommand is None:
        app_command(None)


@app.command("app")
def app_command(recipe: Optional[Path] = typer.Argument(None, show_default=False,
                                                        help="A recipe file to open in the editor.")) -> None:
    """Open the app: translate a recipe, review the action library, roll formulas out in the kitchen."""
    from cook2ltl.ui.app import run_app

    run_app(recipe)


@app.command("doctor")
def doctor_command() -> None:
    """Check the whole stack offline and say what is missing and the command that fixes it."""
    from cook2ltl.doctor import run_checks

    console = Console()
    failures = 0
    for check in run_checks():
        mark = "[green]✓[/green]" if check.ok else "[bold red]✗[/bold red]"
        console.print(f"{mark} {check.name:<28} {escape(check.detail)}")
        if not check.ok:
            failures += 1
            console.print(f"    fix: [bold]{check.fix}[/bold]")
    console.print("[green]all good[/green]" if not failures else f"[bold red]{failures} problem(s)[/bold red]")
    raise typer.Exit(1 if failures else 0)


def main() -> None:
    from cook2ltl import offline

    offline.enforce()
    try:
        for argument in sys.argv[1:]:  # once here, rather than in every command that stores or prints text
            require_utf8(argument, "The argument", "retype it in a UTF-8 terminal.")
        app()
    except UserError as error:
        console = Console(stderr=True)
        console.print(f"[bold red]error:[/bold red] {escape(error.message)}", highlight=False)
        if error.hint:
            console.print(f"[dim]hint:[/dim] {escape(error.hint)}", highlight=False)
        sys.exit(2)
