"""The action library's schema: numbered migrations, run in one transaction when an older file is opened.

MIGRATIONS[n] takes a library from schema version n to n + 1 (SQLite's `user_version`). A migration is
never edited once released: a library written by an older cook2ltl is brought forward in place.
"""

from __future__ import annotations

from pathlib import Path

from sqlite_utils import Database

from cook2ltl.errors import UserError
from cook2ltl.library.faults import DAMAGED_HINT
from cook2ltl.paths import shown
from cook2ltl.reduce.validation import CheckStatus

TABLE = "actions"
VERSIONS = "versions"
REVIEWS = "reviews"
VALIDATIONS = tuple(CheckStatus)  # the kitchen check of a body


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


def _review_versions_and_search(db: Database) -> None:
    """Who reviewed an entry and when, the kitchen check of its body, every body it ever had, and search."""
    checked = ", ".join(f"'{value}'" for value in VALIDATIONS)
    for column in (
        f"validation TEXT NOT NULL DEFAULT 'unchecked' CHECK (validation IN ({checked}))",
        "problems TEXT NOT NULL DEFAULT '[]'",  # JSON list of the kitchen check's messages
        "reviewed_by TEXT",  # who set the current status (approved or rejected), and when
        "reviewed_at TEXT",
        "example TEXT NOT NULL DEFAULT '{}'",  # JSON placeholder → value of the action the body was learnt from
        "version INTEGER NOT NULL DEFAULT 1",  # the current body's number in `versions`
    ):
        db.conn.execute(f"ALTER TABLE {TABLE} ADD COLUMN {column}")
    db.conn.execute(f"""
        CREATE TABLE {VERSIONS} (
            entry_id INTEGER NOT NULL REFERENCES {TABLE} (id),
            version INTEGER NOT NULL,
            body TEXT NOT NULL,
            validation TEXT NOT NULL CHECK (validation IN ({checked})),
            problems TEXT NOT NULL,
            author TEXT NOT NULL,
            at TEXT NOT NULL,
            note TEXT NOT NULL DEFAULT '',
            restores INTEGER,  -- set by undo: the version whose body this one brings back
            PRIMARY KEY (entry_id, version)
        )""")
    db.conn.execute(f"INSERT INTO {VERSIONS} (entry_id, version, body, validation, problems, author, at, note) "
                    f"SELECT id, 1, body, 'unchecked', '[]', model, created, 'learnt' FROM {TABLE}")
    # External-content FTS5 over verb and body; sqlite-utils' triggers keep it in step with every write.
    db[TABLE].enable_fts(["verb", "body"], create_triggers=True, tokenize="porter")


def _review_log(db: Database) -> None:
    """Every approval and rejection, not only the last: who reviewed which version of an entry, and when."""
    statuses = "'pending', 'approved', 'rejected'"
    db.conn.execute(f"""
        CREATE TABLE {REVIEWS} (
            entry_id INTEGER NOT NULL REFERENCES {TABLE} (id),
            version INTEGER NOT NULL,
            status TEXT NOT NULL CHECK (status IN ({statuses})),
            reviewer TEXT NOT NULL,
            at TEXT NOT NULL
        )""")
    db.conn.execute(f"CREATE INDEX reviews_of_entry ON {REVIEWS} (entry_id)")
    db.conn.execute(f"INSERT INTO {REVIEWS} (entry_id, version, status, reviewer, at) "
                    f"SELECT id, version, status, reviewed_by, reviewed_at FROM {TABLE} WHERE reviewed_by IS NOT NULL")


def _intended_effect(db: Database) -> None:
    """The effect an entry's plan must reach, kept with it (see `effect`): a JSON list of atom templates such as
    "boiled(what)"; NULL, as every entry gets here, when it is not recorded."""
    db.conn.execute(f"ALTER TABLE {TABLE} ADD COLUMN effect TEXT")


MIGRATIONS = (_create_actions, _review_versions_and_search, _review_log, _intended_effect)
SCHEMA_VERSION = len(MIGRATIONS)


def schema_version(db: Database, path: Path) -> int:
    """The file's schema version, read without a lock; a newer schema or another program's database is refused."""
    conn, newest = db.conn, len(MIGRATIONS)
    version = conn.execute("PRAGMA user_version").fetchone()[0]
    if version < 0:  # no cook2ltl writes one: the header is damaged
        raise UserError(f"The action library {shown(path)} is damaged (schema version {version}).", DAMAGED_HINT)
    if version > newest:
        raise UserError(f"The action library {shown(path)} has schema version {version}; this cook2ltl knows "
                        f"{newest}.", "upgrade cook2ltl, or use another --library.")
    if version == 0 and conn.execute("SELECT count(*) FROM sqlite_master").fetchone()[0]:
        raise UserError(f"{shown(path)} is an SQLite file but not an action library.",
                        "give --library (or COOK2LTL_LIBRARY) a new path.")
    return version


def is_older(db: Database, path: Path) -> bool:
    """Whether the file needs a migration (a new, empty file does): the one check made on every open."""
    return schema_version(db, path) < len(MIGRATIONS)


def migrate(db: Database, path: Path) -> None:
    """Bring the file to the newest schema; BEGIN IMMEDIATE makes a second process wait, then find it done."""
    conn, newest = db.conn, len(MIGRATIONS)
    conn.execute("BEGIN IMMEDIATE")
    try:
        for number in range(schema_version(db, path), newest):
            MIGRATIONS[number](db)
        conn.execute(f"PRAGMA user_version = {newest}")
        conn.execute("COMMIT")
    except BaseException:
        if conn.in_transaction:  # SQLite may have rolled back already (a full disk)
            conn.execute("ROLLBACK")
        raise
