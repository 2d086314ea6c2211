"""`cook2ltl library`: what the robot will reuse, for a lab to review (list, show, approve, reject)."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

library_app = typer.Typer(help="Review the action library: list, show, approve, reject.", no_args_is_help=True)
LibraryOption = typer.Option(None, "--library", help="Action library file (default: $COOK2LTL_LIBRARY, "
                                                     "else library.sqlite in the user data folder).")
STATUS_STYLE = {"pending": "yellow", "approved": "green", "rejected": "dim"}


def _open(library: Path | None):
    from cook2ltl import paths
    from cook2ltl.library import Library

    return Library(library or paths.library_file())


@library_app.command("list")
def list_command(library: Optional[Path] = LibraryOption,
                 status: Optional[str] = typer.Option(None, help="Only pending, approved or rejected entries.")) -> None:
    """Every entry: id, primitive set, action, status, and the model that wrote it."""
    store = _open(library)
    table = Table("id", "set", "action", "status", "model", "created", title=str(store.path))
    for entry in store.entries():
        if status and entry.status.value != status:
            continue
        table.add_row(str(entry.id), entry.primitives, escape(f"{entry.verb}({', '.join(entry.signature)})"),
                      f"[{STATUS_STYLE[entry.status.value]}]{entry.status.value}[/]", entry.model, entry.created)
    Console().print(table)


@library_app.command("show")
def show_command(entry_id: int, library: Optional[Path] = LibraryOption) -> None:
    """One entry's body and provenance."""
    entry = _find(_open(library), entry_id)
    console = Console()
    console.print(f"[bold]{escape(entry.verb)}[/bold]({escape(', '.join(entry.signature))})  "
                  f"[{STATUS_STYLE[entry.status.value]}]{entry.status.value}[/]")
    console.print(escape(entry.body), highlight=False)
    console.print(f"[dim]set {entry.primitives} · model {entry.model} · prompt {entry.prompt_hash[:12]} · "
                  f"{entry.created}[/dim]")


@library_app.command("approve")
def approve_command(entry_id: int, library: Optional[Path] = LibraryOption) -> None:
    """Mark an entry as reviewed and good."""
    _set(entry_id, "approved", library)


@library_app.command("reject")
def reject_command(entry_id: int, library: Optional[Path] = LibraryOption) -> None:
    """Never reuse an entry: the action is reduced anew the next time it is met."""
    _set(entry_id, "rejected", library)


def _set(entry_id: int, status: str, library: Path | None) -> None:
    from cook2ltl.library.store import Status

    store = _open(library)
    store.set_status(entry_id, Status(status))
    Console().print(f"entry {entry_id}: {status}")


def _find(store, entry_id: int):
    from cook2ltl.errors import UserError

    for entry in store.entries():
        if entry.id == entry_id:
            return entry
    raise UserError(f"No entry {entry_id} in the action library {store.path}.", "`cook2ltl library list` shows them.")
