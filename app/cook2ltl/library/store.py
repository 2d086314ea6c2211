"""The action library 𝔸: parametric reductions in one SQLite file, shared by every run.

One row per learnt action: the primitive set it is written in, the verb, its signature (the categories
it fills), the body with `$what`-style placeholders, a review status, the kitchen check of the body,
where it came from and its intended effect (see `effect`). At most one row per (primitive set, verb,
signature) is live (not rejected); every body an entry ever had is kept in `versions`, every approval
and rejection in `reviews`. A model's reduction is stored pending and never approved by the program: a
person approves it, and that approval wins over any later reduction. An entry with an empty body records
that the model wrote no admissible plan: it spares asking the model again and shows the lab a body to
write; it is never approved, and never a verb that other bodies call. The schema and its migrations are
in `schema`. Each thread gets its own connection (sqlite3 refuses to share one), WAL lets a reader and a
writer work side by side, and every write is one transaction.
"""

from __future__ import annotations

import getpass
import json
import os
import sqlite3
import threading
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, replace
from enum import StrEnum
from pathlib import Path

from sqlite_utils import Database

from cook2ltl.errors import UserError, require_utf8
from cook2ltl.library import versions
from cook2ltl.library.effect import KEEP, Keep, checked_effect, shown_effect
from cook2ltl.library.schema import SCHEMA_VERSION, TABLE, migrate
from cook2ltl.library.versions import Review, Version, checked, now
from cook2ltl.reduce.body import is_empty

__all__ = ["NO_PLAN", "SCHEMA_VERSION", "Library", "LibraryEntry", "Review", "Status", "Version", "reviewer",
           "shown_body"]
REPLACER = "cook2ltl"  # who rejects a pending entry that a new reduction replaces
NO_PLAN = "(no plan)"  # how an empty body is shown
SQLITE_INTEGERS = (-2**63, 2**63 - 1)  # the ids sqlite can store


class Status(StrEnum):
    PENDING = "pending"  # learnt from a model (or edited), used, not yet reviewed
    APPROVED = "approved"
    REJECTED = "rejected"  # never used again; the action is reduced anew when met


@dataclass(frozen=True)
class LibraryEntry:
    id: int
    primitives: str
    verb: str
    signature: tuple[str, ...]
    body: str
    status: Status
    model: str
    prompt_hash: str
    created: str
    validation: str = "unchecked"  # passed, failed or unchecked: the kitchen check of the current body
    problems: tuple[str, ...] = ()  # that check's messages
    reviewed_by: str | None = None  # who set the current status, and when (None: nobody since the last body)
    reviewed_at: str | None = None
    example: tuple[tuple[str, str], ...] = ()  # placeholder → value of the action it was learnt from
    version: int = 1
    effect: tuple[str, ...] | None = None  # atom templates over the slots, such as boiled(what); None: not recorded

    @property
    def action(self) -> str:
        return f"{self.verb}({', '.join(self.signature)})"

    @property
    def has_plan(self) -> bool:
        """False for the record of a reduction with no admissible plan (an empty body)."""
        return not is_empty(self.body)


def shown_body(body: str) -> str:
    return NO_PLAN if is_empty(body) else body


def reviewer() -> str:
    """Who is at the keyboard: $COOK2LTL_USER, else the login name."""
    try:
        name = os.environ.get("COOK2LTL_USER") or getpass.getuser()
    except (KeyError, OSError):  # no login name (a container without a passwd entry)
        return "unknown"
    return require_utf8(name, "COOK2LTL_USER (or the login name)",
                        "set COOK2LTL_USER to a UTF-8 name, or pass --by NAME.")


class Library:
    def __init__(self, path: Path) -> None:
        self.path = path
        self._local = threading.local()
        self._opened: list[Database] = []
        self._lock = threading.Lock()
        self._db()  # open and migrate now, so a bad file is reported before any work

    # --- reading -------------------------------------------------------------------------------------------

    def lookup(self, primitives: str, verb: str, signature: tuple[str, ...],
               approved_only: bool = False) -> LibraryEntry | None:
        """The live entry for an action; with `approved_only` (lab mode) only a reviewed and approved one."""
        rows = self._db()[TABLE].rows_where(
            f"primitives = ? AND verb = ? AND signature = ? AND {_usable(approved_only)}",
            [primitives, verb, ",".join(signature)], limit=1)
        return next((_entry(row) for row in rows), None)

    def live(self, primitives: str, approved_only: bool = False) -> tuple[LibraryEntry, ...]:
        """The entries whose verbs later prompts and bodies may call, oldest first: those with a plan."""
        rows = self._db()[TABLE].rows_where(f"primitives = ? AND trim(body) != '' AND {_usable(approved_only)}",
                                            [primitives], order_by="id")
        return tuple(_entry(row) for row in rows)

    def entries(self) -> tuple[LibraryEntry, ...]:
        return tuple(_entry(row) for row in self._db()[TABLE].rows_where(order_by="id"))

    def get(self, entry_id: int) -> LibraryEntry:
        return _entry(self._row(entry_id))

    def history(self, entry_id: int) -> tuple[Version, ...]:
        """Every body the entry had, oldest first; the last is the current one."""
        self._row(entry_id)
        return versions.history(self._db(), entry_id)

    def reviews(self, entry_id: int) -> tuple[Review, ...]:
        """Every approval and rejection of the entry (and return to pending), oldest first."""
        self._row(entry_id)
        return versions.reviews(self._db(), entry_id)

    def search(self, text: str) -> tuple[LibraryEntry, ...]:
        """Entries whose verb or body match an FTS5 query (words, "a phrase", pick*, boil OR fry), best first."""
        if not text.strip():
            return self.entries()
        try:
            return tuple(_entry(row) for row in self._db()[TABLE].search(text))
        except sqlite3.OperationalError as error:
            raise UserError(f"Cannot search the library for {text!r}: {error}.",
                            'search for words (boil pot), a prefix (pick*), or put text with punctuation '
                            'in double quotes ("put($what").') from error

    # --- writing: each method is one transaction -------------------------------------------------------------

    @contextmanager
    def transaction(self) -> Iterator[Library]:
        """Several writes as one: all of them, or (on an exception) none. Writes inside nest as savepoints."""
        with self._writing():
            yield self

    def add(self, primitives: str, verb: str, signature: tuple[str, ...], body: str, model: str, prompt_hash: str,
            replacing: int | None = None, validation: str = "unchecked", problems: Sequence[str] = (),
            example: Mapping[str, str] | None = None, effect: Sequence[str] | None = None) -> LibraryEntry:
        """Store a model's reduction as a new pending entry (version 1), with its intended effect (atom templates
        such as "boiled(what)"; a bad one is a UserError and nothing is written). `replacing` is a live entry that
        no longer fits: a pending one is rejected in the same transaction, an approved one wins and is returned
        unchanged. If another process stored the same action first, that entry is returned."""
        db = self._db()
        entry = LibraryEntry(0, primitives, verb, signature, body, Status.PENDING, model, prompt_hash, now(),
                             checked(validation), tuple(problems), example=tuple(dict(example or {}).items()),
                             effect=checked_effect(effect))
        try:
            with self._writing():
                old = self._row(replacing, missing_ok=True) if replacing is not None else None
                if old is not None and old["status"] == Status.APPROVED:
                    return _entry(old)
                if old is not None and old["status"] == Status.PENDING:
                    self._set_status(replacing, Status.REJECTED, REPLACER)
                new_id = db[TABLE].insert(_columns(entry)).last_pk
                versions.record(db, Version(new_id, 1, body, validation, entry.problems, model, entry.created,
                                            "learnt"))
        except sqlite3.IntegrityError:
            existing = self.lookup(primitives, verb, signature)
            if existing is None:
                raise
            return existing
        return replace(entry, id=new_id)

    def set_status(self, entry_id: int, status: Status | str, by: str | None = None,
                   force: bool = False) -> LibraryEntry:
        """Approve, reject (or return to pending) an entry, recording who and when. An entry whose body failed
        the kitchen check is approved only with `force`; one without a plan (an empty body) never."""
        status = Status(status)
        with self._writing():
            row = self._row(entry_id)
            entry = _entry(row)
            if status == Status.APPROVED and not entry.has_plan:
                raise UserError(f"Entry {entry_id} ({entry.action}) has no plan: there is nothing to approve.",
                                f"write its body with `cook2ltl library edit {entry_id} --body-file FILE`, "
                                "then approve it.")
            if status == Status.APPROVED and row["validation"] == "failed" and not force:
                raise UserError(f"Entry {entry_id} ({entry.action}) failed the kitchen check: "
                                f"{'; '.join(json.loads(row['problems'])) or 'no details'}.",
                                "fix its body with `cook2ltl library edit`, or approve it anyway with --force.")
            self._set_status(entry_id, status, by or reviewer())
        return self.get(entry_id)

    def edit(self, entry_id: int, body: str, by: str, validation: str = "unchecked", problems: Sequence[str] = (),
             note: str = "", effect: Sequence[str] | None | Keep = KEEP) -> LibraryEntry:
        """A new body (or the same one with another effect) as a new version (the caller checks and validates the
        body first); the entry returns to pending, unreviewed, for someone to approve. `effect`: the new intended
        effect (None: not recorded), checked before anything is written; KEEP leaves it as it is."""
        effect = effect if effect is KEEP else checked_effect(effect)
        with self._writing():
            self._new_version(self._row(entry_id), body, by, validation, tuple(problems), note, effect)
        return self.get(entry_id)

    def undo(self, entry_id: int, by: str) -> LibraryEntry:
        """Bring back the body before the current one, as a new version (pending again); history is never lost."""
        with self._writing():
            row = self._row(entry_id)
            target = versions.undo_target(versions.history(self._db(), entry_id))
            if target is None:
                raise UserError(f"Entry {entry_id} has no earlier version to go back to.",
                                f"`cook2ltl library history {entry_id}` shows its versions.")
            self._new_version(row, target.body, by, target.validation, target.problems,
                              f"undo: back to version {target.version}", KEEP, restores=target.version)
        return self.get(entry_id)

    def insert(self, entry: LibraryEntry, history: Sequence[Version], reviews: Sequence[Review] = ()) -> LibraryEntry:
        """Store an entry as it is, status, every version and review included (an import); its id is new."""
        db = self._db()
        with self._writing():
            try:
                new_id = db[TABLE].insert(_columns(replace(entry, version=history[-1].version))).last_pk
            except sqlite3.IntegrityError as error:
                raise self._taken(entry) from error
            for version in history:
                versions.record(db, replace(version, entry_id=new_id))
            for review in reviews:
                versions.record_review(db, replace(review, entry_id=new_id))
        return self.get(new_id)

    def close(self) -> None:
        with self._lock:
            for db in self._opened:
                db.close()
            self._opened.clear()
        self._local = threading.local()

    @contextmanager
    def _writing(self) -> Iterator[Database]:
        """One write transaction. BEGIN IMMEDIATE takes the write lock before the first read, so a second writer
        waits (busy_timeout) instead of failing on a snapshot the first one changed; nested, a savepoint."""
        db = self._db()
        if db.conn.in_transaction:
            with db.atomic():
                yield db
            return
        db.conn.execute("BEGIN IMMEDIATE")
        try:
            yield db
            db.conn.execute("COMMIT")
        except BaseException:
            if db.conn.in_transaction:
                db.conn.execute("ROLLBACK")
            raise

    # --- inside a transaction ------------------------------------------------------------------------------

    def _row(self, entry_id: int, missing_ok: bool = False) -> dict | None:
        row = None
        if SQLITE_INTEGERS[0] <= entry_id <= SQLITE_INTEGERS[1]:  # sqlite3 overflows on any other int
            row = next(self._db()[TABLE].rows_where("id = ?", [entry_id]), None)
        if row is None and not missing_ok:
            raise UserError(f"No entry {entry_id} in the action library {self.path}.",
                            "`cook2ltl library list` shows them.")
        return row

    def _set_status(self, entry_id: int, status: Status, by: str) -> None:
        db, at = self._db(), now()
        try:
            db.conn.execute(f"UPDATE {TABLE} SET status = ?, reviewed_by = ?, reviewed_at = ? WHERE id = ?",
                            [status.value, by, at, entry_id])
        except sqlite3.IntegrityError as error:
            raise self._taken(self.get(entry_id)) from error
        versions.record_review(db, Review(entry_id, self.get(entry_id).version, status.value, by, at))

    def _new_version(self, row: dict, body: str, by: str, validation: str, problems: tuple[str, ...], note: str,
                     effect: tuple[str, ...] | None | Keep, restores: int | None = None) -> None:
        db = self._db()
        number = row["version"] + 1
        old = _effect(row["effect"])
        effect = old if effect is KEEP else effect
        if effect != old:  # versions keep bodies only: the note tells the history of the new effect
            note = "; ".join(part for part in (note, f"effect: {shown_effect(effect)}") if part)
        versions.record(db, Version(row["id"], number, body, validation, problems, by, now(), note, restores))
        try:
            db.conn.execute(f"UPDATE {TABLE} SET body = ?, validation = ?, problems = ?, version = ?, status = ?, "
                            "reviewed_by = NULL, reviewed_at = NULL, effect = ? WHERE id = ?",
                            [body, validation, json.dumps(list(problems)), number, Status.PENDING.value,
                             _effect_column(effect), row["id"]])
        except sqlite3.IntegrityError as error:
            raise self._taken(_entry(row)) from error

    def _taken(self, entry: LibraryEntry) -> UserError:
        live = self.lookup(entry.primitives, entry.verb, entry.signature)
        if live is None:  # gone again by the time we looked: another process's write
            return UserError(f"The library changed while writing {entry.action}.", "try again.")
        return UserError(f"Entry {live.id} is already the live {entry.action} for {entry.primitives}: "
                         "there can be only one.", f"reject entry {live.id} first.")

    # --- connections ---------------------------------------------------------------------------------------

    def _db(self) -> Database:
        db = getattr(self._local, "db", None)
        if db is None:
            db = self._connect()
            self._local.db = db
            with self._lock:
                self._opened.append(db)
        return db

    def _connect(self) -> Database:
        if self.path.exists() and not self.path.is_file():
            raise UserError(f"The action library {self.path} is not a file.", "give --library a file path.")
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            # Each thread keeps to its own connection; the flag only lets close() end them all.
            conn = sqlite3.connect(self.path, check_same_thread=False)
        except (OSError, sqlite3.Error) as error:
            raise UserError(f"Cannot open the action library {self.path}: {error}.",
                            "give --library (or COOK2LTL_LIBRARY) a writable path.") from error
        try:
            db = Database(conn)
            conn.execute("PRAGMA busy_timeout = 10000")  # wait for another process's write
            migrate(db, self.path)
            db.enable_wal()  # after the check, so another program's SQLite file is left as it was
        except sqlite3.DatabaseError as error:
            conn.close()
            raise UserError(f"{self.path} is not an action library ({error}).",
                            "give --library (or COOK2LTL_LIBRARY) a new path, or move that file away.") from error
        except BaseException:
            conn.close()
            raise
        return db


def _usable(approved_only: bool) -> str:
    return "status = 'approved'" if approved_only else "status != 'rejected'"


def _columns(entry: LibraryEntry) -> dict:
    """An entry as a row of `actions`, without its id."""
    return {
        "primitives": entry.primitives, "verb": entry.verb, "signature": ",".join(entry.signature),
        "body": entry.body, "status": Status(entry.status).value, "model": entry.model,
        "prompt_hash": entry.prompt_hash, "created": entry.created, "validation": checked(entry.validation),
        "problems": json.dumps(list(entry.problems)), "reviewed_by": entry.reviewed_by,
        "reviewed_at": entry.reviewed_at, "example": json.dumps(dict(entry.example)), "version": entry.version,
        "effect": _effect_column(entry.effect),
    }


def _entry(row: dict) -> LibraryEntry:
    return LibraryEntry(
        id=row["id"], primitives=row["primitives"], verb=row["verb"],
        signature=tuple(part for part in row["signature"].split(",") if part), body=row["body"],
        status=Status(row["status"]), model=row["model"], prompt_hash=row["prompt_hash"], created=row["created"],
        validation=row["validation"], problems=tuple(json.loads(row["problems"])), reviewed_by=row["reviewed_by"],
        reviewed_at=row["reviewed_at"], example=tuple(json.loads(row["example"]).items()), version=row["version"],
        effect=_effect(row["effect"]),
    )


def _effect_column(effect: tuple[str, ...] | None) -> str | None:
    return None if effect is None else json.dumps(list(effect))


def _effect(column: str | None) -> tuple[str, ...] | None:
    return None if column is None else tuple(json.loads(column))
