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
An entry with no plan is never approved, so a file that approves one is refused.
The whole file is checked before anything is written, and it is imported in one transaction.
"""

from __future__ import annotations

import json
import os
import tempfile
from dataclasses import dataclass
from datetime import datetime
from pathlib import Path

from cook2ltl.errors import UserError
from cook2ltl.library.effect import KEEP, checked_effect
from cook2ltl.library.schema import SCHEMA_VERSION, VALIDATIONS
from cook2ltl.library.store import Library, LibraryEntry, Status
from cook2ltl.library.versions import Review, Version, now
from cook2ltl.reduce.body import read_body

ADDED, UNCHANGED, REPLACED, CONFLICT = "added", "unchanged", "replaced", "conflict"
READABLE = range(2, SCHEMA_VERSION + 1)  # export files this cook2ltl reads
HINT = "export a library with `cook2ltl library export FILE` to see the format."


@dataclass(frozen=True)
class Exported:
    """One entry of an export file, with every version and review."""

    entry: LibraryEntry
    history: tuple[Version, ...]
    reviews: tuple[Review, ...]


@dataclass(frozen=True)
class ImportReport:
    added: tuple[str, ...] = ()  # "recipe boil(what)" for each entry new here
    unchanged: tuple[str, ...] = ()
    replaced: tuple[str, ...] = ()  # pending entries given the file's body as a new version
    conflicts: tuple[str, ...] = ()  # "recipe boil(what): why it was left as it is"


def export_library(library: Library, path: Path) -> int:
    """Write every entry with its history; returns how many. The file appears whole or not at all."""
    entries = [_record(Exported(entry, library.history(entry.id), library.reviews(entry.id)))
               for entry in library.entries()]
    text = json.dumps({"schema_version": SCHEMA_VERSION, "exported": now(), "entries": entries},
                      indent=2, ensure_ascii=False)
    temporary = None
    try:
        handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
        with os.fdopen(handle, "w", encoding="utf-8") as file:
            file.write(text + "\n")
        os.replace(temporary, path)
    except OSError as error:
        if temporary is not None:
            Path(temporary).unlink(missing_ok=True)
        raise UserError(f"Cannot write {path}: {error.strerror or error}.", "give a writable file path.") from error
    return len(entries)


def import_library(library: Library, path: Path, by: str, replace_pending: bool = False) -> ImportReport:
    records = read_export(path)
    known: dict[tuple, list[LibraryEntry]] = {}
    for entry in library.entries():
        known.setdefault(_key(entry), []).append(entry)
    report: dict[str, list[str]] = {ADDED: [], UNCHANGED: [], REPLACED: [], CONFLICT: []}
    note = f"imported from {path.name}"
    with library.transaction():
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
                                                       note, effect)
                label += f" (entry {local.id})"
            report[outcome].append(f"{label}: {reason}" if reason else label)
    return ImportReport(*(tuple(report[outcome]) for outcome in (ADDED, UNCHANGED, REPLACED, CONFLICT)))


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


def read_export(path: Path) -> list[Exported]:
    """The entries of an export file, each checked field by field; any fault is a UserError naming it."""
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError as error:
        raise UserError(f"{path} is not a JSON library export (it is not text).", HINT) from error
    except OSError as error:
        raise UserError(f"Cannot read {path}: {error.strerror or error}.",
                        "give the path of an export file.") from error
    try:
        data = json.loads(text)
        json.dumps(data, ensure_ascii=False).encode("utf-8")  # a \udcff escape is JSON but not storable text
    except json.JSONDecodeError as error:
        raise UserError(f"{path} is not valid JSON: {error.msg} at line {error.lineno}, column {error.colno}.",
                        HINT) from error
    except UnicodeEncodeError as error:
        raise UserError(f"{path} is not a library export: it has text that is not Unicode "
                        f"({error.object[error.start:error.end]!r}, a lone surrogate).", HINT) from error
    except RecursionError as error:
        raise UserError(f"{path} is not a library export: its JSON nests too deeply.", HINT) from error
    except ValueError as error:  # an integer of thousands of digits
        raise UserError(f"{path} is not a library export: {error}.", HINT) from error
    if not isinstance(data, dict) or "schema_version" not in data:
        raise UserError(f"{path} is not a library export: it has no \"schema_version\".", HINT)
    version = data["schema_version"]
    if isinstance(version, bool) or version not in READABLE:
        raise UserError(f"{path} has schema version {version!r}; this cook2ltl reads versions "
                        f"{READABLE[0]} to {READABLE[-1]}.", "export it again with this cook2ltl, or upgrade cook2ltl.")
    entries = data.get("entries")
    if not isinstance(entries, list):
        raise UserError(f"{path}: \"entries\" must be a list of entries.", HINT)
    return [_read_entry(raw, f"{path}: entry {number}") for number, raw in enumerate(entries, start=1)]


def _read_entry(raw, where: str) -> Exported:
    fields = _Fields(raw, where)
    signature = fields.words("signature")
    body = fields.body("body")
    history = fields.get("history", list)
    if not history:
        raise UserError(f"{where}: \"history\" must list at least the current version.", HINT)
    versions = tuple(_read_version(item, f"{where}, version {n}") for n, item in enumerate(history, start=1))
    numbers = [v.version for v in versions]
    if numbers != sorted(set(numbers)) or versions[-1].body != body:
        raise UserError(f"{where}: \"history\" must go up in version numbers and end with the current body.", HINT)
    entry = LibraryEntry(
        id=0, primitives=fields.text("primitives"), verb=fields.text("verb"), signature=signature, body=body,
        status=Status(fields.choice("status", tuple(Status))), model=fields.text("model"),
        prompt_hash=fields.get("prompt_hash", str), created=fields.time("created"),
        validation=fields.choice("validation", VALIDATIONS), problems=fields.words("problems"),
        reviewed_by=fields.get("reviewed_by", str, optional=True),
        reviewed_at=fields.time("reviewed_at", optional=True), example=fields.example(), version=numbers[-1],
        effect=fields.effect(),
    )
    if entry.status == Status.APPROVED and not entry.has_plan:
        raise UserError(f"{where}: an entry with no plan (an empty \"body\") cannot be approved.", HINT)
    reviews = tuple(_read_review(item, f"{where}, review {n}", numbers)
                    for n, item in enumerate(fields.get("reviews", list, optional=True) or (), start=1))
    return Exported(entry, versions, reviews)


def _read_review(raw, where: str, numbers: list[int]) -> Review:
    fields = _Fields(raw, where)
    version = fields.get("version", int)
    if version not in numbers:
        raise UserError(f"{where}: \"version\" {version} is not in the entry's history.", HINT)
    return Review(0, version, fields.choice("status", tuple(Status)), fields.text("reviewer"), fields.time("at"))


def _read_version(raw, where: str) -> Version:
    fields = _Fields(raw, where)
    number = fields.get("version", int)
    restores = fields.get("restores", int, optional=True)
    if number < 1 or (restores is not None and not 1 <= restores < number):
        raise UserError(f"{where}: version numbers start at 1, and a restored version is an earlier one.", HINT)
    return Version(0, number, fields.body("body"), fields.choice("validation", VALIDATIONS),
                   fields.words("problems"), fields.text("author"), fields.time("at"), fields.get("note", str),
                   restores)


class _Fields:
    """Typed reads of one JSON object, each fault a UserError naming the entry and the field."""

    def __init__(self, raw, where: str) -> None:
        if not isinstance(raw, dict):
            raise UserError(f"{where} is not a JSON object.", HINT)
        self.raw, self.where = raw, where

    def get(self, name: str, kind: type, optional: bool = False):
        value = self.raw.get(name)
        if value is None and optional:
            return None
        if not isinstance(value, kind) or isinstance(value, bool):
            raise UserError(f"{self.where}: \"{name}\" must be {_KINDS[kind]}, not {json.dumps(value)}.", HINT)
        return value

    def text(self, name: str) -> str:
        value = self.get(name, str)
        if not value.strip():
            raise UserError(f"{self.where}: \"{name}\" is empty.", HINT)
        return value

    def choice(self, name: str, allowed: tuple[str, ...]) -> str:
        value = self.get(name, str)
        if value not in allowed:
            raise UserError(f"{self.where}: \"{name}\" must be one of {', '.join(allowed)}, not {value!r}.", HINT)
        return value

    def words(self, name: str) -> tuple[str, ...]:
        value = self.get(name, list)
        if not all(isinstance(item, str) for item in value):
            raise UserError(f"{self.where}: \"{name}\" must be a list of strings.", HINT)
        return tuple(value)

    def time(self, name: str, optional: bool = False) -> str | None:
        value = self.get(name, str, optional)
        try:
            if value is not None:
                datetime.fromisoformat(value)
        except ValueError as error:
            raise UserError(f"{self.where}: \"{name}\" must be an ISO 8601 time, not {value!r}.", HINT) from error
        return value

    def body(self, name: str) -> str:
        """Calls one a line; empty for an entry with no plan."""
        value = self.get(name, str)
        _, unread = read_body(value)
        if unread:
            raise UserError(f"{self.where}: \"{name}\" has a line that is not a call: {unread[0]!r}.", HINT)
        return value

    def example(self) -> tuple[tuple[str, str], ...]:
        value = self.get("example", dict)
        if not all(key.startswith("$") and isinstance(item, str) for key, item in value.items()):
            raise UserError(f"{self.where}: \"example\" must map placeholders such as \"$what\" to values.", HINT)
        return tuple(value.items())

    def effect(self) -> tuple[str, ...] | None:
        """Atom templates such as "boiled(what)"; None when the file records none."""
        value = self.get("effect", list, optional=True)
        if value is not None and not all(isinstance(item, str) for item in value):
            raise UserError(f"{self.where}: \"effect\" must be a list of atoms such as \"boiled(what)\".", HINT)
        return checked_effect(value, f"{self.where}: \"effect\"")


_KINDS = {str: "a string", int: "a whole number", list: "a list", dict: "an object"}


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
