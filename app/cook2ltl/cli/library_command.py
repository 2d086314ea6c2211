"""`cook2ltl library`: what the robot will reuse, for a lab to review, correct and share.

list, show, approve, reject, edit, history, undo, export, import. Every change records who made it (`--by`,
default $COOK2LTL_USER or the login name) and when; an edited body is checked against the primitive set and
run in the embedded kitchen before it is stored, an edited intended effect is checked atom by atom.
"""

from __future__ import annotations

from contextlib import ExitStack
from pathlib import Path
from typing import Optional

import typer
from rich.console import Console
from rich.table import Table
from rich.text import Text

from cook2ltl import paths
from cook2ltl.errors import UserError
from cook2ltl.files import decoded, read_bytes, read_stdin
from cook2ltl.paths import shown, user_path
from cook2ltl.reduce.validation import CheckStatus
from cook2ltl.text_safety import literal, styled, terminal

library_app = typer.Typer(help="Review the action library: list, show, approve, reject, edit, history, undo, "
                               "export, import.", no_args_is_help=True)
LibraryOption = typer.Option(None, "--library", help="Action library file (default: $COOK2LTL_LIBRARY, "
                                                     "else library.sqlite in the user data folder).")
ByOption = typer.Option(None, "--by", help="Who makes the change (default: $COOK2LTL_USER, else the login name).")
STATUS_STYLE = {"pending": "yellow", "approved": "green", "rejected": "dim"}
CHECK_STYLE = {CheckStatus.PASSED: "green", CheckStatus.FAILED: "bold red", CheckStatus.UNCHECKED: "dim"}


def _open(library: Path | None, read_only: bool = False):
    """The library; `read_only` for a command that only reads (it then never waits for another's write)."""
    # startup: `cook2ltl --help` imports this module; the library (sqlite-utils) loads when the command runs
    from cook2ltl.library import Library

    library = paths.user_path(library, "--library") if library else None
    return Library(library or paths.library_file(), read_only)


def _by(by: str | None) -> str:
    # startup: `cook2ltl --help` imports this module; the library (sqlite-utils) loads when the command runs
    from cook2ltl.library import reviewer

    return by or reviewer()


@library_app.command("list")
def list_command(library: Optional[Path] = LibraryOption,
                 status: Optional[str] = typer.Option(None, help="Only pending, approved or rejected entries."),
                 search: Optional[str] = typer.Option(None, help="Only entries whose verb or body match these words "
                                                                 "(full-text: boil pot, pick*, \"put($what\"), "
                                                                 "best match first.")) -> None:
    """Every entry: id, primitive set, action, status, kitchen check, version, reviewer and model."""
    if status is not None and status not in STATUS_STYLE:
        raise UserError(f"--status {status!r} is not one of {', '.join(STATUS_STYLE)}.", "leave it out to list all.")
    # startup: `cook2ltl --help` imports this module; the library (sqlite-utils) loads when the command runs
    from cook2ltl.library.store import NO_PLAN

    store = _open(library, read_only=True)
    entries = store.search(search) if search else store.entries()
    table = Table("id", "set", "action", "status", "check", "v", "reviewed", "model", title=literal(store.path))
    for entry in entries:
        if status and entry.status.value != status:
            continue
        reviewed = f"{entry.reviewed_by} {entry.reviewed_at[:10]}" if entry.reviewed_by else ""
        action = entry.action if entry.has_plan else f"{entry.action} {NO_PLAN}"
        table.add_row(str(entry.id), literal(entry.primitives), literal(action), _status(entry.status.value),
                      _check(entry.validation), str(entry.version), literal(reviewed), literal(entry.model))
    if table.row_count:
        terminal().print(table)
        return
    wanted = (f" matching {search!r}" if search else "") + (f" with status {status}" if status else "")
    terminal(highlight=False).print(f"no entries{wanted} in {store.path}")


@library_app.command("show")
def show_command(entry_id: int, library: Optional[Path] = LibraryOption) -> None:
    """One entry: body, status and reviewer, kitchen check and its problems, intended effect, provenance, version."""
    # startup: `cook2ltl --help` imports this module; the library (sqlite-utils) loads when the command runs
    from cook2ltl.library.effect import shown_effect
    from cook2ltl.library.store import shown_body

    entry = _open(library, read_only=True).get(entry_id)
    console = terminal(highlight=False)
    review = (f" by {entry.reviewed_by} at {entry.reviewed_at}" if entry.reviewed_by
              else "" if entry.status.value != "pending" else ", not reviewed yet")
    console.print(styled((entry.action, "bold"), "  ", _status(entry.status.value), review))
    console.print(styled(f"version {entry.version} · kitchen check ", _check(entry.validation)))
    for problem in entry.problems:
        console.print(styled("  ", ("✗", "red"), " ", problem))
    console.print(f"effect: {shown_effect(entry.effect)}")
    console.print()
    console.print(shown_body(entry.body))
    console.print()
    if entry.example:
        console.print(literal("learnt from " + ", ".join(f"{k} = {v}" for k, v in entry.example), "dim"))
    console.print(literal(f"set {entry.primitives} · model {entry.model} · prompt {entry.prompt_hash[:12]} · "
                          f"created {entry.created}", "dim"))


@library_app.command("approve")
def approve_command(entry_id: int, library: Optional[Path] = LibraryOption, by: Optional[str] = ByOption,
                    force: bool = typer.Option(False, "--force", help="Approve even a body that failed the kitchen "
                                                                      "check.")) -> None:
    """Mark an entry as reviewed and good: lab mode (--approved-only) reuses only approved entries."""
    _set(entry_id, "approved", library, by, force)


@library_app.command("reject")
def reject_command(entry_id: int, library: Optional[Path] = LibraryOption, by: Optional[str] = ByOption) -> None:
    """Never reuse an entry: the action is reduced anew the next time it is met."""
    _set(entry_id, "rejected", library, by, False)


def _set(entry_id: int, status: str, library: Path | None, by: str | None, force: bool) -> None:
    entry = _open(library).set_status(entry_id, status, by=_by(by), force=force)
    terminal(highlight=False).print(styled(f"entry {entry_id} {entry.action}: ", _status(status),
                                           f" by {entry.reviewed_by}"))


@library_app.command("edit")
def edit_command(entry_id: int,
                 body_file: Optional[str] = typer.Option(None, "--body-file", help="The new body, one call per line; "
                                                         "- reads it from standard input (default: keep the body)."),
                 effect: Optional[list[str]] = typer.Option(
                     None, "--effect", help="An atom of the intended effect, such as boiled(what) or in(what, pot); "
                                            "repeat it for each atom; none: nothing to reach (default: keep it)."),
                 clear_effect: bool = typer.Option(False, "--clear-effect",
                                                   help="Forget the intended effect: not recorded."),
                 library: Optional[Path] = LibraryOption, by: Optional[str] = ByOption,
                 note: str = typer.Option("", help="Why the entry changed, kept in the history."),
                 keep_failing: bool = typer.Option(False, "--keep-failing",
                                                   help="Save the body even if it fails the kitchen check."),
                 validate: bool = typer.Option(True, "--validate/--no-validate",
                                               help="Run the body in the embedded kitchen (else: unchecked)."),
                 primitives: Optional[str] = typer.Option(
                     None, help="The primitive set file of an entry in a lab's own set (built-ins load by name)."),
                 ) -> None:
    """Replace an entry's body (checked line by line, run in the kitchen) or its intended effect (checked atom by
    atom), or both: stored as a new version, pending. A new effect alone keeps the body's kitchen check."""
    # startup: `cook2ltl --help` imports this module; the library (sqlite-utils) loads when the command runs
    from cook2ltl.library.body_check import body_problems
    from cook2ltl.library.effect import KEEP
    from cook2ltl.library.recheck import Recheck, live_verbs

    store = _open(library)
    entry = store.get(entry_id)
    new_effect = _effect_option(effect, clear_effect, body_file is None)
    body = entry.body if body_file is None else _read_body(body_file)
    console, errors = terminal(highlight=False), terminal(stderr=True, highlight=False)
    if new_effect == entry.effect:
        new_effect = KEEP
    if body == entry.body and new_effect is KEEP:
        console.print(f"entry {entry_id}: the body and the effect are unchanged; nothing saved")
        return
    if body == entry.body:
        _save(store, entry, body, by, Recheck(entry.validation, entry.problems), note, new_effect, console)
        return
    primitive_set = _primitive_set(primitives or entry.primitives, entry.primitives)
    verbs = live_verbs(store, entry.primitives)
    problems = body_problems(body, entry.verb, entry.signature, primitive_set, verbs)
    if problems:
        for problem in problems:
            errors.print(styled(("✗", "bold red"), " ", problem))
        errors.print(f"nothing saved: entry {entry_id} keeps version {entry.version}")
        raise typer.Exit(2)
    checked = _kitchen_check(entry, body, primitive_set, verbs) if validate else Recheck(CheckStatus.UNCHECKED, ())
    for problem in checked.problems:
        console.print(styled("  ", ("✗", "red"), " ", problem))
    if checked.validation == CheckStatus.FAILED and not keep_failing:
        errors.print(styled(("the body fails the kitchen check", "bold red"),
                            "; nothing saved (--keep-failing saves it anyway)"))
        raise typer.Exit(1)
    _save(store, entry, body, by, checked, note, new_effect, console)


def _save(store, entry, body: str, by: str | None, checked, note: str, effect, console: Console) -> None:
    # startup: `cook2ltl --help` imports this module; the library (sqlite-utils) loads when the command runs
    from cook2ltl.library.effect import shown_effect

    # `expected`: if someone approved or edited the entry meanwhile, nothing is saved over their change.
    edited = store.edit(entry.id, body, _by(by), checked.validation, checked.problems, note, effect, expected=entry)
    console.print(styled(f"entry {entry.id} {edited.action}: version {edited.version}, kitchen check ",
                         _check(edited.validation), f", effect {shown_effect(edited.effect)}, ", _status("pending"),
                         " review"))


def _effect_option(atoms: list[str] | None, clear: bool, no_body: bool):
    """The edit's effect: KEEP, None (--clear-effect), () (--effect none) or the atoms, checked."""
    # startup: `cook2ltl --help` imports this module; the library (sqlite-utils) loads when the command runs
    from cook2ltl.library.effect import KEEP, checked_effect

    if atoms and clear:
        raise UserError("--effect and --clear-effect contradict each other.", "give one of them.")
    if not atoms and not clear and no_body:
        raise UserError("Nothing to edit.", "give --body-file FILE, --effect ATOM or --clear-effect.")
    if clear:
        return None
    if not atoms:
        return KEEP
    return () if atoms == ["none"] else checked_effect(atoms, "--effect")


def _read_body(body_file: str) -> str:
    """The body from a regular file or standard input: at most limits.BODY_BYTES of UTF-8 text."""
    # startup: `cook2ltl --help` imports this module; the library (sqlite-utils) loads when the command runs
    from cook2ltl.library.limits import BODY_BYTES

    hint = "give a text file with one call per line, or - to read standard input."
    if body_file == "-":
        return decoded(read_stdin(BODY_BYTES, hint), "Standard input").strip()
    path = user_path(body_file, "--body-file")
    return decoded(read_bytes(path, BODY_BYTES, "body file", hint), f"The body file {shown(path)}").strip()


def _primitive_set(choice: str, name: str):
    # startup: `cook2ltl --help` imports this module; pydantic and the kitchen load when the command runs
    from cook2ltl.reduce.primitives import load_primitives

    primitive_set = load_primitives(choice)
    if primitive_set.name != name:
        raise UserError(f"The entry is written in the primitive set {name!r}, not {primitive_set.name!r}.",
                        f"give --primitives the file of the set {name!r}.")
    return primitive_set


def _kitchen_check(entry, body, primitive_set, verbs):
    # startup: `cook2ltl --help` imports this module; pydantic and the kitchen load when the command runs
    from cook2ltl.assembly.edits import edited_body_check
    from cook2ltl.execution.kitchen_check import KitchenValidator

    with ExitStack() as closing:
        def kitchen():
            closing.enter_context(terminal(stderr=True).status("running the body in the kitchen …"))
            return closing.enter_context(KitchenValidator(primitive_set))

        return edited_body_check(entry, body, primitive_set, verbs, kitchen)


@library_app.command("history")
def history_command(entry_id: int, library: Optional[Path] = LibraryOption) -> None:
    """Every body the entry had, who wrote it and when, and who approved or rejected which version."""
    # startup: `cook2ltl --help` imports this module; the library (sqlite-utils) loads when the command runs
    from cook2ltl.library.store import shown_body

    store = _open(library, read_only=True)
    entry = store.get(entry_id)
    table = Table("v", "at", "by", "check", "note", "body", title=literal(f"entry {entry_id} {entry.action}"),
                  show_lines=True)
    for version in store.history(entry_id):
        table.add_row(str(version.version), literal(version.at[:16].replace("T", " ")), literal(version.author),
                      _check(version.validation), literal(version.note), literal(shown_body(version.body)))
    console = terminal(highlight=False)
    console.print(table)
    for review in store.reviews(entry_id):
        console.print(styled(f"version {review.version} ", _status(review.status),
                             f" by {review.reviewer} at {review.at}"))


@library_app.command("undo")
def undo_command(entry_id: int, library: Optional[Path] = LibraryOption, by: Optional[str] = ByOption) -> None:
    """Bring back the body before the current one, as a new version for review; nothing is lost."""
    store = _open(library)
    entry = store.undo(entry_id, _by(by))
    restored = store.history(entry_id)[-1].restores
    terminal(highlight=False).print(styled(
        f"entry {entry_id} {entry.action}: the body of version {restored} is back as version {entry.version}, "
        "kitchen check ", _check(entry.validation), ", ", _status("pending"), " review"))


@library_app.command("export")
def export_command(file: Path, library: Optional[Path] = LibraryOption) -> None:
    """Write every entry with its history to a JSON file, for another lab or robot."""
    # startup: `cook2ltl --help` imports this module; the library (sqlite-utils) loads when the command runs
    from cook2ltl.library.exchange import export_library

    store = _open(library, read_only=True)
    count = export_library(store, file)
    terminal(highlight=False).print(f"{count} entr{'y' if count == 1 else 'ies'} from {store.path} written to {file}")


@library_app.command("import")
def import_command(file: Path, library: Optional[Path] = LibraryOption, by: Optional[str] = ByOption,
                   replace_pending: bool = typer.Option(False, "--replace-pending",
                                                        help="A pending entry with another body gets the file's "
                                                             "body as a new version (approved ones are never "
                                                             "replaced)."),
                   force: bool = typer.Option(False, "--force", help="Keep the approval of approved entries whose "
                                                                     "body failed the kitchen check (as approve "
                                                                     "--force).")) -> None:
    """Add the entries of an export file: new ones added, the same ones left, conflicts reported, never overwritten."""
    # startup: `cook2ltl --help` imports this module; the library (sqlite-utils) loads when the command runs
    from cook2ltl.library.exchange import import_library

    report = import_library(_open(library), file, _by(by), replace_pending, force)
    console = terminal(highlight=False)
    for heading, items, style in (("added", report.added, "green"), ("replaced", report.replaced, "yellow"),
                                  ("conflict", report.conflicts, "bold red")):
        for item in items:
            console.print(styled((heading, style), " ", item))
    console.print(f"{len(report.added)} added, {len(report.unchanged)} unchanged, {len(report.replaced)} replaced, "
                  f"{len(report.conflicts)} conflict(s)")


def _status(status: str) -> Text:
    return literal(status, STATUS_STYLE.get(status, ""))


def _check(validation: str) -> Text:
    return literal(validation, CHECK_STYLE.get(validation, ""))
