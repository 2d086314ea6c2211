"""The action library 𝔸: parametric reductions in one SQLite file, shared by every run.

One row per learnt action: the primitive set it is written in, the verb, its signature (the categories
it fills), the body with `$what`-style placeholders, a review status and where it came from. At most one
row per (primitive set, verb, signature) is live (not rejected). The schema version is SQLite's
`user_version`; migrations are numbered functions run in one transaction. Each thread gets its own
connection (sqlite3 refuses to share one), and WAL lets a reader and a writer work side by side.
"""

from __future__ import annotations

import sqlite3
import threading
from dataclasses import dataclass
from datetime import datetime, timezone
from enum import StrEnum
from pathlib import Path

from sqlite_utils import Database

from cook2ltl.errors import UserError

TABLE = "actions"


class Status(StrEnum):
    PENDING = "pending"  # learnt from a model, used, not yet reviewed
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


def _create_actions(db: Database) -> None:
    db.conn.execute(f"""
        CREATE TABLE {TABLE} (
            id INTEGER PRIMARY KEY,
            primitives TEXT NOT NULL,
            verb TEXT NOT NULL,
            signature TEXT NOT NULL,
            body TEXT NOT NULL,
            status TEXT NOT NULL DEFAULT 'pending' CHECK (status IN ('pending', 'approved', 'rejected')),
            model TEXT NOT NULL,
            prompt_hash TEXT NOT NULL,
            created TEXT NOT NULL
        )""")
    db.conn.execute(f"CREATE UNIQUE INDEX one_live_entry ON {TABLE} (primitives, verb, signature) "
                    "WHERE status != 'rejected'")


MIGRATIONS = (_create_actions,)  # MIGRATIONS[n] takes a library from schema version n to n + 1
SCHEMA_VERSION = len(MIGRATIONS)


class Library:
    def __init__(self, path: Path) -> None:
        self.path = path
        self._local = threading.local()
        self._opened: list[Database] = []
        self._lock = threading.Lock()
        self._db()  # open and migrate now, so a bad file is reported before any work

    def lookup(self, primitives: str, verb: str, signature: tuple[str, ...]) -> LibraryEntry | None:
        rows = self._db()[TABLE].rows_where(
            "primitives = ? AND verb = ? AND signature = ? AND status != 'rejected'",
            [primitives, verb, ",".join(signature)], limit=1)
        return next((_entry(row) for row in rows), None)

    def live(self, primitives: str) -> tuple[LibraryEntry, ...]:
        """The entries a translation may use, oldest first: their verbs join later prompts."""
        rows = self._db()[TABLE].rows_where("primitives = ? AND status != 'rejected'", [primitives], order_by="id")
        return tuple(_entry(row) for row in rows)

    def entries(self) -> tuple[LibraryEntry, ...]:
        return tuple(_entry(row) for row in self._db()[TABLE].rows_where(order_by="id"))

    def add(self, primitives: str, verb: str, signature: tuple[str, ...], body: str, model: str, prompt_hash: str,
            replacing: int | None = None) -> LibraryEntry:
        """Store a new pending entry; `replacing` is a live entry that no longer fits, rejected in the
        same transaction. If another process stored the same action first, that entry is returned."""
        db = self._db()
        row = {
            "primitives": primitives, "verb": verb, "signature": ",".join(signature), "body": body,
            "status": Status.PENDING.value, "model": model, "prompt_hash": prompt_hash,
            "created": datetime.now(timezone.utc).isoformat(timespec="seconds"),
        }
        try:
            with db.atomic():
                if replacing is not None:
                    db[TABLE].update(replacing, {"status": Status.REJECTED.value})
                new_id = db[TABLE].insert(row).last_pk
        except sqlite3.IntegrityError:
            existing = self.lookup(primitives, verb, signature)
            if existing is None:
                raise
            return existing
        return _entry({**row, "id": new_id})

    def set_status(self, entry_id: int, status: Status) -> None:
        db = self._db()
        with db.atomic():
            if db.execute(f"UPDATE {TABLE} SET status = ? WHERE id = ?", [Status(status).value, entry_id]).rowcount != 1:
                raise UserError(f"No entry {entry_id} in the action library {self.path}.")

    def close(self) -> None:
        with self._lock:
            for db in self._opened:
                db.close()
            self._opened.clear()
        self._local = threading.local()

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
            _migrate(db, self.path)
            db.enable_wal()  # after the check, so another program's SQLite file is left as it was
        except sqlite3.DatabaseError as error:
            conn.close()
            raise UserError(f"{self.path} is not an action library ({error}).",
                            "give --library (or COOK2LTL_LIBRARY) a new path, or move that file away.") from error
        except BaseException:
            conn.close()
            raise
        return db


def _migrate(db: Database, path: Path) -> None:
    """Bring the file to SCHEMA_VERSION; BEGIN IMMEDIATE makes a second process wait, then find it done."""
    conn = db.conn
    conn.execute("BEGIN IMMEDIATE")
    try:
        version = conn.execute("PRAGMA user_version").fetchone()[0]
        if version > SCHEMA_VERSION:
            raise UserError(f"The action library {path} has schema version {version}; this cook2ltl knows {SCHEMA_VERSION}.",
                            "upgrade cook2ltl, or use another --library.")
        if version == 0 and conn.execute("SELECT count(*) FROM sqlite_master").fetchone()[0]:
            raise UserError(f"{path} is an SQLite file but not an action library.",
                            "give --library (or COOK2LTL_LIBRARY) a new path.")
        for number in range(version, SCHEMA_VERSION):
            MIGRATIONS[number](db)
        conn.execute(f"PRAGMA user_version = {SCHEMA_VERSION}")
        conn.execute("COMMIT")
    except BaseException:
        conn.execute("ROLLBACK")
        raise


def _entry(row: dict) -> LibraryEntry:
    return LibraryEntry(
        id=row["id"], primitives=row["primitives"], verb=row["verb"],
        signature=tuple(part for part in row["signature"].split(",") if part), body=row["body"],
        status=Status(row["status"]), model=row["model"], prompt_hash=row["prompt_hash"], created=row["created"],
    )
