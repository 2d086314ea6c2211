"""SQLite's failures as a user meets them: a locked, full, read-only, damaged or foreign library file, each
said for what it is. Only a file that is not an SQLite database is called "not an action library": the other
faults pass, and moving the file away would lose the work in it."""

from __future__ import annotations

import sqlite3
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from cook2ltl.errors import UserError
from cook2ltl.paths import shown

# SQLite's primary result codes (https://sqlite.org/rescode.html); an extended code keeps them in its low byte.
SQL_ERROR = 1  # the statement itself is at fault (such as a search query's syntax)
PERM, BUSY, LOCKED, READONLY, IOERR, CORRUPT, FULL, CANTOPEN, NOTADB = 3, 5, 6, 8, 10, 11, 13, 14, 26
READONLY_DBMOVED = READONLY | (4 << 8)  # the file was renamed or replaced while open


DAMAGED_HINT = "restore it from a backup or an export; `sqlite3 FILE .recover` may save its entries."


class DamagedRow(Exception):
    """A row the program cannot read: a column missing, JSON that is not, a status it does not know."""


@contextmanager
def reading_rows() -> Iterator[None]:
    """Rows made into entries and versions: what cannot be read in one is the library's damage, not a bug."""
    try:
        yield
    except (KeyError, TypeError, ValueError, AttributeError) as error:
        raise DamagedRow(f"{type(error).__name__}: {error}") from error


@contextmanager
def reported(path: Path) -> Iterator[None]:
    """Any sqlite3 error inside, raised again as the UserError that says what happened."""
    try:
        yield
    except sqlite3.Error as error:
        raise library_error(error, path) from error
    except (DamagedRow, UnicodeDecodeError) as error:  # text in the file that is not UTF-8 is damage too
        raise UserError(f"The action library {shown(path)} is damaged ({_one_line(error)}).", DAMAGED_HINT) \
            from error


def library_error(error: sqlite3.Error, path: Path) -> UserError:
    extended = getattr(error, "sqlite_errorcode", None) or 0
    code, where = extended & 0xFF, shown(path)
    if code in (BUSY, LOCKED):
        return UserError(f"The action library {where} is locked: another cook2ltl process is writing to it.",
                         "try again when it has finished (an import or a translation can take minutes).")
    if code == FULL:
        return UserError(f"The disk of the action library {where} is full; nothing was written.",
                         "free some space on it, then try again.")
    if extended == READONLY_DBMOVED:
        return UserError(f"The action library {where} was moved or replaced while in use; nothing was written.",
                         "run the command again on the file where it is now.")
    if code in (READONLY, PERM):
        return UserError(f"The action library {where} is read-only; nothing was written.",
                         "make the file and its folder writable, or give --library a writable copy.")
    if code == NOTADB:
        return UserError(f"{where} is not an action library ({_one_line(error)}).",
                         "give --library (or COOK2LTL_LIBRARY) a new path, or move that file away.")
    if code == CORRUPT or (extended == 0 and "decode" in str(error)):  # text in the schema that is not UTF-8
        return UserError(f"The action library {where} is damaged ({_one_line(error)}).", DAMAGED_HINT)
    if code == CANTOPEN:
        return UserError(f"Cannot open the action library {where} ({_one_line(error)}).",
                         "give --library (or COOK2LTL_LIBRARY) a file in a folder you can write.")
    if code == IOERR:
        return UserError(f"Cannot read or write the action library {where}: {_one_line(error)}.",
                         "check the disk it is on, then try again.")
    return UserError(f"The action library {where} failed: {_one_line(error)}.", "try again; nothing was written.")


def _one_line(error: Exception) -> str:
    """SQLite's message on one line and short: a damaged schema's can quote the whole table."""
    text = " ".join(str(error).split())
    return text if len(text) <= 200 else f"{text[:199]}…"
