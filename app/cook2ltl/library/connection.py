"""Opening the library file. Opening never takes the write lock unless the file is new or of an older schema, so
a reading command (list, show, export) works while another process imports for minutes; a reading command's
connection is read-only, so it cannot write by mistake either."""

from __future__ import annotations

import os
import sqlite3
import stat
from pathlib import Path
from urllib.parse import quote

from sqlite_utils import Database

from cook2ltl.errors import UserError
from cook2ltl.library.faults import reported
from cook2ltl.library.safe_write import file_status, reason
from cook2ltl.library.schema import is_older, migrate
from cook2ltl.paths import shown

BUSY_TIMEOUT_MS = 10_000  # how long a write waits for another process's write before it reports the lock


def open_library(path: Path, read_only: bool) -> Database:
    """A connection to the library at `path`, which is created or brought to the newest schema first if need
    be (the one write a reading command may make). A fault is a UserError that says what it is."""
    found = file_status(path, "the action library")
    if found is not None and not stat.S_ISREG(found.st_mode):
        raise UserError(f"The action library {shown(path)} is not a file.", "give --library a file path.")
    if found is None:
        _make_folder(path)
        _migrate_apart(path)  # the first command to open a library creates it
    db = _connect(path, read_only)
    try:
        with reported(path):
            if is_older(db, path):
                if read_only:
                    _migrate_apart(path)
                else:
                    migrate(db, path)
            if not read_only:
                db.enable_wal()  # after the checks, so another program's SQLite file is left as it was
    except BaseException:
        db.close()
        raise
    return db


def _migrate_apart(path: Path) -> None:
    """Create or migrate the file through a writable connection of its own, closed when done."""
    writer = _connect(path, read_only=False)
    try:
        with reported(path):
            migrate(writer, path)
            writer.enable_wal()
    finally:
        writer.close()


def _connect(path: Path, read_only: bool) -> Database:
    with reported(path):
        if read_only:
            conn = sqlite3.connect(f"file:{quote(os.path.abspath(path))}?mode=ro", uri=True, check_same_thread=False)
        else:
            # Each thread keeps to its own connection; the flag only lets Library.close() end them all.
            conn = sqlite3.connect(path, check_same_thread=False)
        try:
            conn.execute(f"PRAGMA busy_timeout = {BUSY_TIMEOUT_MS}")  # wait for another process's write
        except BaseException:
            conn.close()
            raise
    return Database(conn)


def _make_folder(path: Path) -> None:
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise UserError(f"Cannot create the folder of the action library {shown(path)}: {reason(error)}.",
                        "give --library (or COOK2LTL_LIBRARY) a path in a folder you can write.") from error
