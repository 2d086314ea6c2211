"""The command line: `cook2ltl` alone (or `cook2ltl app`) opens the app; `parse | translate | rollout | library |
ltl | models | doctor` are headless."""

from __future__ import annotations

import importlib
import sys
from pathlib import Path
from typing import Optional

import click
import typer
from typer.core import TyperGroup

from cook2ltl import offline
from cook2ltl.errors import UserError, require_utf8
from cook2ltl.text_safety import literal, styled, terminal

# The headless commands, imported only when run or listed: `cook2ltl app` starts without loading them.
COMMANDS = {
    "parse": ("cook2ltl.cli.parse_command", "parse_command"),
    "translate": ("cook2ltl.cli.translate_command", "translate_command"),
    "rollout": ("cook2ltl.cli.rollout_command", "rollout_command"),
    "bench": ("cook2ltl.cli.bench_command", "bench_command"),
    "library": ("cook2ltl.cli.library_command", "library_app"),
    "models": ("cook2ltl.cli.models_command", "models_app"),
    "ltl": ("cook2ltl.ltl.cli", "ltl_app"),
}


class LazyCommands(TyperGroup):
    """The top-level group: a command in COMMANDS is imported and built (by Typer, as if registered eagerly)
    the first time it is looked up."""

    def list_commands(self, ctx: click.Context) -> list[str]:
        return [*COMMANDS, *super().list_commands(ctx)]

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        if name in COMMANDS and name not in self.commands:
            self.commands[name] = _built(name)
        return super().get_command(ctx, name)


def _built(name: str) -> click.Command:
    module, attribute = COMMANDS[name]
    target = getattr(importlib.import_module(module), attribute)
    holder = typer.Typer()
    if isinstance(target, typer.Typer):
        holder.add_typer(target, name=name)
    else:
        holder.command(name)(target)
    return typer.main.get_group(holder).commands[name]


app = typer.Typer(help="Cooking recipes to LTL task specifications, offline. Without a command: the app.",
                  pretty_exceptions_enable=False, cls=LazyCommands)


@app.callback(invoke_without_command=True)
def open_app_by_default(context: typer.Context) -> None:
    if context.invoked_subcommand is None:
        app_command(None)


@app.command("app")
def app_command(recipe: Optional[Path] = typer.Argument(None, show_default=False,
                                                        help="A recipe file to open in the editor.")) -> None:
    """Open the app: translate a recipe, review the action library, roll formulas out in the kitchen."""
    from cook2ltl.ui.app import run_app  # startup: Textual and the app load only for `cook2ltl app`

    run_app(recipe)


@app.command("doctor")
def doctor_command() -> None:
    """Check the whole stack offline and say what is missing and the command that fixes it."""
    # startup: the checks load when `cook2ltl doctor` runs, not with every command
    from cook2ltl.assembly.doctor import run_checks

    console = terminal()
    failures = 0
    for check in run_checks():
        mark = ("✓", "green") if check.ok else ("✗", "bold red")
        console.print(styled(mark, f" {check.name:<28} {check.detail}"))
        if not check.ok:
            failures += 1
            console.print(styled("    fix: ", (check.fix, "bold")))
    console.print(literal("all good", "green") if not failures else literal(f"{failures} problem(s)", "bold red"))
    raise typer.Exit(1 if failures else 0)


def main() -> None:
    offline.enforce()
    try:
        for argument in sys.argv[1:]:  # once here, rather than in every command that stores or prints text
            require_utf8(argument, "The argument", "retype it in a UTF-8 terminal.")
        app()
    except UserError as error:
        console = terminal(stderr=True)
        console.print(styled(("error:", "bold red"), " ", error.message), highlight=False)
        if error.hint:
            console.print(styled(("hint:", "dim"), " ", error.hint), highlight=False)
        sys.exit(2)
