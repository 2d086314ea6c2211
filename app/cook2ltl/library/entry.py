"""A library entry, as the program sees it and as a row of `actions` stores it."""

from __future__ import annotations

import json
from dataclasses import dataclass
from enum import StrEnum

from cook2ltl.library.faults import reading_rows
from cook2ltl.library.versions import checked
from cook2ltl.reduce.body import is_empty
from cook2ltl.reduce.validation import CheckStatus

NO_PLAN = "(no plan)"  # how an empty body is shown


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
    validation: CheckStatus = CheckStatus.UNCHECKED  # the kitchen check of the current body
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


def as_row(entry: LibraryEntry) -> dict:
    """An entry as a row of `actions`, without its id."""
    return {
        "primitives": entry.primitives, "verb": entry.verb, "signature": ",".join(entry.signature),
        "body": entry.body, "status": Status(entry.status).value, "model": entry.model,
        "prompt_hash": entry.prompt_hash, "created": entry.created, "validation": checked(entry.validation),
        "problems": json.dumps(list(entry.problems)), "reviewed_by": entry.reviewed_by,
        "reviewed_at": entry.reviewed_at, "example": json.dumps(dict(entry.example)), "version": entry.version,
        "effect": effect_column(entry.effect),
    }


def from_row(row: dict) -> LibraryEntry:
    with reading_rows():
        return LibraryEntry(
            id=_whole(row["id"]), primitives=_text(row["primitives"]), verb=_text(row["verb"]),
            signature=tuple(part for part in row["signature"].split(",") if part), body=_text(row["body"]),
            status=Status(row["status"]), model=_text(row["model"]), prompt_hash=row["prompt_hash"],
            created=row["created"],
            validation=CheckStatus(row["validation"]), problems=tuple(json.loads(row["problems"])),
            reviewed_by=row["reviewed_by"], reviewed_at=row["reviewed_at"],
            example=tuple(json.loads(row["example"]).items()), version=_whole(row["version"]),
            effect=effect_of(row["effect"]),
        )


def _whole(value: object) -> int:
    """A column that must hold a whole number (a damaged file may hold NULL or text there)."""
    if not isinstance(value, int) or isinstance(value, bool):
        raise TypeError(f"{value!r} where a whole number belongs")
    return value


def _text(value: object) -> str:
    if not isinstance(value, str):
        raise TypeError(f"{value!r} where text belongs")
    return value


def effect_column(effect: tuple[str, ...] | None) -> str | None:
    return None if effect is None else json.dumps(list(effect))


def effect_of(column: str | None) -> tuple[str, ...] | None:
    return None if column is None else tuple(json.loads(column))
