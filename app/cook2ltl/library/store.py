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
writer work side by side, and every write is one transaction that reads what it changes (a status, a version)
inside it. Every SQLite failure reaches the caller as a UserError that names it (see `faults`).
"""

from __future__ import annotations

import functools
import getpass
import json
import os
import sqlite3
import threading
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import TypeVar

from sqlite_utils import Database

from cook2ltl.errors import UserError, require_utf8
from cook2ltl.library import versions
from cook2ltl.library.connection import open_library
from cook2ltl.library.effect import KEEP, Keep, checked_effect, shown_effect
from cook2ltl.library.entry import NO_PLAN, LibraryEntry, Status, as_row, effect_column, effect_of, from_row, shown_body
from cook2ltl.library.faults import SQL_ERROR, DamagedRow, reported
from cook2ltl.library.schema import SCHEMA_VERSION, TABLE
from cook2ltl.library.versions import Review, Version, checked, now
from cook2ltl.paths import shown, user_path
from cook2ltl.reduce.validation import CheckStatus

__all__ = ["NO_PLAN", "SCHEMA_VERSION", "Library", "LibraryEntry", "Review", "Status", "Version", "reviewer",
           "shown_body"]
REPLACER = "cook2ltl"  # who rejects a pending entry that a new reduction replaces
SQLITE_INTEGERS = (-2**63, 2**63 - 1)  # the ids sqlite can store
Method = TypeVar("Method", bound=Callable)


def reviewer() -> str:
    """Who is at the keyboard: $COOK2LTL_USER, else the login name."""
    try:
        name = os.environ.get("COOK2LTL_USER") or getpass.getuser()
    except (KeyError, OSError):  # no login name (a container without a passwd entry)
        return "unknown"
    return require_utf8(name, "COOK2LTL_USER (or the login name)",
                        "set COOK2LTL_USER to a UTF-8 name, or pass --by NAME.")


def _reported(method: Method) -> Method:
    """A Library method whose SQLite failures (a lock held too long, a full disk …) are UserErrors."""
    @functools.wraps(method)
    def reporting(self: Library, *args, **kwargs):
        with reported(self.path):
            return method(self, *args, **kwargs)
    return reporting  # type: ignore[return-value]


class Library:
    def __init__(self, path: Path | str, read_only: bool = False) -> None:
        """The library at `path` (`~` expanded). `read_only`: for commands that only read; nothing can be written
        then, and opening needs no lock (unless the file is new or of an older schema)."""
        self.path = user_path(path, "The action library")
        self.read_only = read_only
        self._local = threading.local()
        self._opened: list[Database] = []
        self._lock = threading.Lock()
        self._db()  # open and migrate now, so a bad file is reported before any work

    # --- reading -------------------------------------------------------------------------------------------

    @_reported
    def lookup(self, primitives: str, verb: str, signature: tuple[str, ...],
               approved_only: bool = False) -> LibraryEntry | None:
        """The live entry for an action; with `approved_only` (lab mode) only a reviewed and approved one."""
        rows = self._db()[TABLE].rows_where(
            f"primitives = ? AND verb = ? AND signature = ? AND {_usable(approved_only)}",
            [primitives, verb, ",".join(signature)], limit=1)
        return next((from_row(row) for row in rows), None)

    @_reported
    def live(self, primitives: str, approved_only: bool = False) -> tuple[LibraryEntry, ...]:
        """The entries whose verbs later prompts and bodies may call, oldest first: those with a plan."""
        rows = self._db()[TABLE].rows_where(f"primitives = ? AND trim(body) != '' AND {_usable(approved_only)}",
                                            [primitives], order_by="id")
        return tuple(from_row(row) for row in rows)

    @_reported
    def entries(self) -> tuple[LibraryEntry, ...]:
        return tuple(from_row(row) for row in self._db()[TABLE].rows_where(order_by="id"))

    @_reported
    def get(self, entry_id: int) -> LibraryEntry:
        return from_row(self._row(entry_id))

    @_reported
    def history(self, entry_id: int) -> tuple[Version, ...]:
        """Every body the entry had, oldest first; the last is the current one."""
        self._row(entry_id)
        return versions.history(self._db(), entry_id)

    @_reported
    def reviews(self, entry_id: int) -> tuple[Review, ...]:
        """Every approval and rejection of the entry (and return to pending), oldest first."""
        self._row(entry_id)
        return versions.reviews(self._db(), entry_id)

    @_reported
    def search(self, text: str) -> tuple[LibraryEntry, ...]:
        """Entries whose verb or body match an FTS5 query (words, "a phrase", pick*, boil OR fry), best first."""
        if not text.strip():
            return self.entries()
        try:
            return tuple(from_row(row) for row in self._db()[TABLE].search(text))
        except ValueError as error:  # sqlite-utils finds no full-text index: the file lost it
            raise DamagedRow(f"the search index is gone ({error})") from error
        except sqlite3.OperationalError as error:
            if getattr(error, "sqlite_errorcode", None) != SQL_ERROR:  # a lock, a full disk, damage: not the query
                raise
            raise UserError(f"Cannot search the library for {text!r}: {error}.",
                            'search for words (boil pot), a prefix (pick*), or put text with punctuation '
                            'in double quotes ("put($what").') from error

    # --- writing: each method is one transaction -------------------------------------------------------------

    @contextmanager
    def transaction(self) -> Iterator[Library]:
        """Several writes as one: all of them, or (on an exception) none. Writes inside nest as savepoints;
        reads inside see what no other process can change until the end (the write lock is held)."""
        with reported(self.path), self._writing():
            yield self

    @contextmanager
    def snapshot(self) -> Iterator[Library]:
        """Several reads as one: all of them see the library as it was at the first (WAL keeps that snapshot
        while other processes write), and none waits for a lock."""
        db = self._db()
        if db.conn.in_transaction:
            yield self
            return
        with reported(self.path):
            db.conn.execute("BEGIN")
        try:
            yield self
        finally:
            if db.conn.in_transaction:
                db.conn.execute("ROLLBACK")  # it only read

    @_reported
    def add(self, primitives: str, verb: str, signature: tuple[str, ...], body: str, model: str, prompt_hash: str,
            replacing: int | None = None, validation: CheckStatus = CheckStatus.UNCHECKED, problems: Sequence[str] = (),
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
                    return from_row(old)
                if old is not None and old["status"] == Status.PENDING:
                    self._set_status(replacing, Status.REJECTED, REPLACER)
                new_id = db[TABLE].insert(as_row(entry)).last_pk
                versions.record(db, Version(new_id, 1, body, validation, entry.problems, model, entry.created,
                                            "learnt"))
        except sqlite3.IntegrityError:
            existing = self.lookup(primitives, verb, signature)
            if existing is None:
                raise
            return existing
        return replace(entry, id=new_id)

    @_reported
    def set_status(self, entry_id: int, status: Status | str, by: str | None = None,
                   force: bool = False) -> LibraryEntry:
        """Approve, reject (or return to pending) an entry, recording who and when. An entry whose body failed
        the kitchen check is approved only with `force`; one without a plan (an empty body) never."""
        status = Status(status)
        with self._writing():
            row = self._row(entry_id)
            entry = from_row(row)
            if status == Status.APPROVED and not entry.has_plan:
                raise UserError(f"Entry {entry_id} ({entry.action}) has no plan: there is nothing to approve.",
                                f"write its body with `cook2ltl library edit {entry_id} --body-file FILE`, "
                                "then approve it.")
            if status == Status.APPROVED and row["validation"] == CheckStatus.FAILED and not force:
                raise UserError(f"Entry {entry_id} ({entry.action}) failed the kitchen check: "
                                f"{'; '.join(json.loads(row['problems'])) or 'no details'}.",
                                "fix its body with `cook2ltl library edit`, or approve it anyway with --force.")
            self._set_status(entry_id, status, by or reviewer())
        return self.get(entry_id)

    @_reported
    def edit(self, entry_id: int, body: str, by: str, validation: CheckStatus = CheckStatus.UNCHECKED,
             problems: Sequence[str] = (), note: str = "", effect: Sequence[str] | None | Keep = KEEP,
             expected: LibraryEntry | None = None) -> LibraryEntry:
        """A new body (or the same one with another effect) as a new version (the caller checks and validates the
        body first); the entry returns to pending, unreviewed, for someone to approve. `effect`: the new intended
        effect (None: not recorded), checked before anything is written; KEEP leaves it as it is. `expected`: the
        entry as the caller read it; if its status or version is another by now (someone approved or edited it
        meanwhile), nothing is written and that is a UserError: compared and set in one transaction."""
        effect = effect if effect is KEEP else checked_effect(effect)
        with self._writing():
            row = self._row(entry_id)
            if expected is not None and (row["status"], row["version"]) != (expected.status.value, expected.version):
                raise UserError(f"Entry {entry_id} ({expected.action}) changed meanwhile: it is {row['status']} "
                                f"version {row['version']} now, not {expected.status.value} version "
                                f"{expected.version}; nothing saved.",
                                f"look at it with `cook2ltl library show {entry_id}`, then try again.")
            self._new_version(row, body, by, validation, tuple(problems), note, effect)
        return self.get(entry_id)

    @_reported
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

    @_reported
    def insert(self, entry: LibraryEntry, history: Sequence[Version], reviews: Sequence[Review] = ()) -> LibraryEntry:
        """Store an entry as it is, status, every version and review included (an import); its id is new."""
        db = self._db()
        with self._writing():
            try:
                new_id = db[TABLE].insert(as_row(replace(entry, version=history[-1].version))).last_pk
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
            raise UserError(f"No entry {entry_id} in the action library {shown(self.path)}.",
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

    def _new_version(self, row: dict, body: str, by: str, validation: CheckStatus, problems: tuple[str, ...], note: str,
                     effect: tuple[str, ...] | None | Keep, restores: int | None = None) -> None:
        db = self._db()
        number = row["version"] + 1
        old = effect_of(row["effect"])
        effect = old if effect is KEEP else effect
        if effect != old:  # versions keep bodies only: the note tells the history of the new effect
            note = "; ".join(part for part in (note, f"effect: {shown_effect(effect)}") if part)
        versions.record(db, Version(row["id"], number, body, validation, problems, by, now(), note, restores))
        try:
            db.conn.execute(f"UPDATE {TABLE} SET body = ?, validation = ?, problems = ?, version = ?, status = ?, "
                            "reviewed_by = NULL, reviewed_at = NULL, effect = ? WHERE id = ?",
                            [body, validation, json.dumps(list(problems)), number, Status.PENDING.value,
                             effect_column(effect), row["id"]])
        except sqlite3.IntegrityError as error:
            raise self._taken(from_row(row)) from error

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
            db = open_library(self.path, self.read_only)
            self._local.db = db
            with self._lock:
                self._opened.append(db)
        return db


def _usable(approved_only: bool) -> str:
    return "status = 'approved'" if approved_only else "status != 'rejected'"
