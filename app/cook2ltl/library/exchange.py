"""A library as a JSON file, to move reviewed actions between labs and robots, every version included.

    {"schema_version": 4, "exported": "2026-…", "entries": [{"primitives": "recipe", "verb": "boil",
     "signature": ["what"], "body": "…", "status": "approved", "model": "…", "prompt_hash": "…",
     "created": "…", "validation": "passed", "problems": [], "reviewed_by": "ann", "reviewed_at": "…",
     "example": {"$what": "egg"}, "effect": ["boiled(what)"], "history": [{"version": 1, "body": "…",
     "validation": "passed", "problems": [], "author": "…", "at": "…", "note": "learnt", "restores": null}, …],
     "reviews": [{"version": 1, "status": "approved", "reviewer": "ann", "at": "…"}, …]}, …]}

Files of schema version 2 (before the review log) are read too, their entries without "reviews"; an entry
without "effect" (or with null) has none recorded.

Import compares each entry with this library's entries for the same action (primitive set, verb, signature):
- none here: added with its status, versions and reviews, plus one version saying who imported it;
- the same body here, with the same effect unless the file records none (or, for an entry the file
  rejects, the same body already rejected here): unchanged;
- an approved entry here with another body or effect: a conflict, never overwritten;
- a pending entry here with another body or effect: a conflict, unless `replace_pending`, which adds the
  file's body (and effect, if it records one) to it as a new version (still pending, for review);
- a rejected entry in the file whose body is live here: a conflict, for the lab to review; other rejected
  entries are added as records;
- a live entry in the file whose body was rejected here: a conflict, kept rejected;
- an entry with no plan (an empty body, see `store`) in the file, for an action with a live plan here: a
  conflict, even with `replace_pending` (no plan never replaces one).
An entry with no plan is never approved, so a file that approves one is refused; an approved entry whose body
failed the kitchen check is imported only with `force` (as `approve --force`). The whole file is checked
before anything is written (`exchange_format`), and it is imported in one transaction that reads this
library's entries inside it, so an entry approved meanwhile by another process is never replaced.

An export reads one snapshot of the library and is written whole or not at all; it never replaces the library
itself (or its -wal and -shm files), another SQLite database, or anything but a regular file.
"""

from __future__ import annotations

import json
import os
import stat
from dataclasses import dataclass
from pathlib import Path

from cook2ltl.errors import UserError
from cook2ltl.library.effect import KEEP
from cook2ltl.library.exchange_format import Exported, read_export
from cook2ltl.library.safe_write import file_status, replace_whole
from cook2ltl.library.schema import SCHEMA_VERSION
from cook2ltl.library.store import Library, LibraryEntry, Status
from cook2ltl.library.versions import Version, now
from cook2ltl.paths import shown, user_path
from cook2ltl.reduce.validation import CheckStatus

ADDED, UNCHANGED, REPLACED, CONFLICT = "added", "unchanged", "replaced", "conflict"
SQLITE_HEADER = b"SQLite format 3\x00"
LIBRARY_FILES = ("", "-wal", "-shm", "-journal")  # the library and the files SQLite keeps beside it


@dataclass(frozen=True)
class ImportReport:
    added: tuple[str, ...] = ()  # "recipe boil(what)" for each entry new here
    unchanged: tuple[str, ...] = ()
    replaced: tuple[str, ...] = ()  # pending entries given the file's body as a new version
    conflicts: tuple[str, ...] = ()  # "recipe boil(what): why it was left as it is"


def export_library(library: Library, path: Path) -> int:
    """Write every entry with its history; returns how many. The file appears whole or not at all."""
    path = user_path(path, "The export file")
    hint = "give the path of a new or an export file, away from the library."
    _refuse_library_files(path, library.path, hint)
    with library.snapshot():
        entries = [_record(Exported(entry, library.history(entry.id), library.reviews(entry.id)))
                   for entry in library.entries()]
    text = json.dumps({"schema_version": SCHEMA_VERSION, "exported": now(), "entries": entries},
                      indent=2, ensure_ascii=False)
    replace_whole(path, (text + "\n").encode("utf-8"), hint)
    return len(entries)


def _refuse_library_files(path: Path, library: Path, hint: str) -> None:
    """An export never replaces the library it is written from (by any name: a link, a hard link), the files
    SQLite keeps beside it, or any other SQLite database: replacing one loses the entries in it."""
    target, base = os.path.realpath(path), os.path.realpath(library)
    found = file_status(Path(target), "the export file")
    for suffix in LIBRARY_FILES:
        beside = file_status(Path(base + suffix), "the action library") if found is not None else None
        if target == base + suffix or (beside is not None and os.path.samestat(found, beside)):
            what = f"the action library's {suffix} file" if suffix else "the action library"
            raise UserError(f"Cannot export to {shown(path)}: it is {what}, and the export would destroy the "
                            "library.", hint)
    if found is not None and stat.S_ISREG(found.st_mode) and _starts_with(Path(target), SQLITE_HEADER):
        raise UserError(f"Cannot export to {shown(path)}: it is an SQLite database, which the export would "
                        "replace.", hint)


def _starts_with(path: Path, header: bytes) -> bool:
    try:
        with open(path, "rb") as file:
            return file.read(len(header)) == header
    except OSError:
        return False


def import_library(library: Library, path: Path, by: str, replace_pending: bool = False,
                   force: bool = False) -> ImportReport:
    """Add the entries of an export file as the module's docstring says; `force` keeps the approval of entries
    whose body failed the kitchen check."""
    path = user_path(path, "The export file")
    records = read_export(path)
    if not force:
        _refuse_failed_approvals(records, path)
    report: dict[str, list[str]] = {ADDED: [], UNCHANGED: [], REPLACED: [], CONFLICT: []}
    note = f"imported from {path.name}"
    with library.transaction():
        known: dict[tuple, list[LibraryEntry]] = {}
        for entry in library.entries():  # read under the write lock: nobody changes them until the end
            known.setdefault(_key(entry), []).append(entry)
        for record in records:
            entry = record.entry
            label = f"{entry.primitives} {entry.action}"
            here = known.setdefault(_key(entry), [])
            outcome, local, reason = _outcome(entry, here, replace_pending)
            if outcome == ADDED:
                here.append(_insert(library, record, by, note))
            elif outcome == REPLACED:
                effect = KEEP if entry.effect is None else entry.effect
                here[here.index(local)] = library.edit(local.id, entry.body, by, entry.validation, entry.problems,
                                                       note, effect, expected=local)
                label += f" (entry {local.id})"
            report[outcome].append(f"{label}: {reason}" if reason else label)
    return ImportReport(*(tuple(report[outcome]) for outcome in (ADDED, UNCHANGED, REPLACED, CONFLICT)))


def _refuse_failed_approvals(records: list[Exported], path: Path) -> None:
    for number, record in enumerate(records, start=1):
        entry = record.entry
        if entry.status == Status.APPROVED and entry.validation == CheckStatus.FAILED:
            problems = " ".join("; ".join(entry.problems).split())[:200] or "no details"  # on one line
            raise UserError(f"{shown(path)}: entry {number} ({entry.primitives} {entry.action}) is approved but "
                            f"failed the kitchen check: {problems}.",
                            "import with --force to keep its approval (as `approve --force`), or fix the entry "
                            "in the library it comes from.")


def _outcome(entry: LibraryEntry, here: list[LibraryEntry],
             replace_pending: bool) -> tuple[str, LibraryEntry | None, str]:
    """What importing `entry` does, given this library's entries for the same action: the outcome, the local
    entry it concerns, and for a conflict, why."""
    rejected = entry.status == Status.REJECTED
    live = next((e for e in here if e.status != Status.REJECTED), None)
    if any(e.body == entry.body and (e.status == Status.REJECTED) == rejected and (rejected or _same_effect(entry, e))
           for e in here):  # a rejected entry is a record: its effect does not matter
        return UNCHANGED, None, ""
    if rejected:
        if live is not None and live.body == entry.body:
            return CONFLICT, live, f"the file rejects the body of entry {live.id}, {live.status} here; review it"
        return ADDED, None, ""  # a record of what another lab refused; never reused
    refused = next((e for e in here if e.status == Status.REJECTED and e.body == entry.body), None)
    if refused is not None:
        return CONFLICT, refused, f"entry {refused.id} rejected this body here; kept rejected"
    if live is None:
        return ADDED, None, ""
    other = "effect" if live.body == entry.body else "body"
    if live.status == Status.APPROVED:
        return CONFLICT, live, f"entry {live.id} is approved here with another {other}; kept"
    if not entry.has_plan:
        return CONFLICT, live, f"the file has no plan for it; entry {live.id} keeps its body"
    if not replace_pending:
        return CONFLICT, live, (f"entry {live.id} is pending here with another {other}; kept "
                                f"(--replace-pending adds the file's {other} to it as a new version)")
    return REPLACED, live, ""


def _same_effect(entry: LibraryEntry, here: LibraryEntry) -> bool:
    """A file that records no effect (an older export) says nothing against the effect here."""
    return entry.effect is None or entry.effect == here.effect


def _insert(library: Library, record: Exported, by: str, note: str) -> LibraryEntry:
    """The entry as the file has it, plus one version that says who imported it from where."""
    entry = record.entry
    stamp = Version(0, record.history[-1].version + 1, entry.body, entry.validation, entry.problems, by, now(), note)
    return library.insert(entry, (*record.history, stamp), record.reviews)


def _insert(library: Library, record: Exported, by: str, note: str) -> LibraryEntry:
    """The entry as the file has it, plus one version that says who imported it from where."""
    entry = record.entry
    stamp = Version(0, record.history[-1].version + 1, entry.body, entry.validation, entry.problems, by, now(), note)
    return library.insert(entry, (*record.history, stamp), record.reviews)


def _record(record: Exported) -> dict:
    entry = record.entry
    return {
        "primitives": entry.primitives, "verb": entry.verb, "signature": list(entry.signature), "body": entry.body,
        "status": entry.status.value, "model": entry.model, "prompt_hash": entry.prompt_hash,
        "created": entry.created, "validation": entry.validation, "problems": list(entry.problems),
        "reviewed_by": entry.reviewed_by, "reviewed_at": entry.reviewed_at, "example": dict(entry.example),
        "effect": None if entry.effect is None else list(entry.effect),
        "history": [{"version": v.version, "body": v.body, "validation": v.validation, "problems": list(v.problems),
                     "author": v.author, "at": v.at, "note": v.note, "restores": v.restores} for v in record.history],
        "reviews": [{"version": r.version, "status": r.status, "reviewer": r.reviewer, "at": r.at}
                    for r in record.reviews],
    }


def _key(entry: LibraryEntry) -> tuple:
    return entry.primitives, entry.verb, entry.signature
