"""Every body a library entry ever had (`versions`, written by add, edit and undo) and every review of it
(`reviews`, written by each status change): an entry's history."""

from __future__ import annotations

import json
from dataclasses import dataclass
from datetime import datetime, timezone

from sqlite_utils import Database

from cook2ltl.library.faults import reading_rows
from cook2ltl.library.schema import REVIEWS, VALIDATIONS, VERSIONS
from cook2ltl.reduce.validation import CheckStatus


@dataclass(frozen=True)
class Version:
    entry_id: int
    version: int
    body: str
    validation: CheckStatus  # the kitchen check of this body
    problems: tuple[str, ...]
    author: str  # the model that learnt it, or the person who edited, undid or imported it
    at: str
    note: str
    restores: int | None = None  # undo: the version whose body this one brings back


@dataclass(frozen=True)
class Review:
    entry_id: int
    version: int  # the version that was approved or rejected
    status: str
    reviewer: str
    at: str


def now() -> str:
    return datetime.now(timezone.utc).isoformat(timespec="seconds")


def checked(validation: str) -> CheckStatus:
    if validation not in VALIDATIONS:
        raise ValueError(f"validation must be one of {', '.join(VALIDATIONS)}, not {validation!r}")
    return CheckStatus(validation)


def record(db: Database, version: Version) -> None:
    """Store one version; the caller holds the transaction that also updates the entry."""
    db.conn.execute(
        f"INSERT INTO {VERSIONS} (entry_id, version, body, validation, problems, author, at, note, restores) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
        [version.entry_id, version.version, version.body, checked(version.validation), json.dumps(version.problems),
         version.author, version.at, version.note, version.restores])


def history(db: Database, entry_id: int) -> tuple[Version, ...]:
    rows = db[VERSIONS].rows_where("entry_id = ?", [entry_id], order_by="version")
    with reading_rows():
        return tuple(Version(entry_id=row["entry_id"], version=row["version"], body=row["body"],
                             validation=CheckStatus(row["validation"]), problems=tuple(json.loads(row["problems"])),
                             author=row["author"], at=row["at"], note=row["note"], restores=row["restores"])
                     for row in rows)


def undo_target(versions: tuple[Version, ...]) -> Version | None:
    """The version an undo brings back: the one before the current body's own. A restored version counts as
    the one it restores, so undoing again keeps stepping back instead of flipping between two bodies."""
    current = versions[-1]
    wanted = (current.restores or current.version) - 1
    return next((v for v in versions if v.version == wanted), None)


def record_review(db: Database, review: Review) -> None:
    db.conn.execute(f"INSERT INTO {REVIEWS} (entry_id, version, status, reviewer, at) VALUES (?, ?, ?, ?, ?)",
                    [review.entry_id, review.version, review.status, review.reviewer, review.at])


def reviews(db: Database, entry_id: int) -> tuple[Review, ...]:
    rows = db[REVIEWS].rows_where("entry_id = ?", [entry_id], order_by="rowid")
    with reading_rows():
        return tuple(Review(row["entry_id"], row["version"], row["status"], row["reviewer"], row["at"]) for row in rows)
