"""Reading an export file: the edge where JSON from another lab becomes typed library entries.

Each entry is checked by pydantic models (strict: a number is never a string, a boolean never a number), with a
bound on every number, string and list (see `limits`), and a fault is a one-line UserError naming the file, the
entry and the field. The file is read only if it is a regular file no larger than `limits.EXPORT_BYTES`.
"""

from __future__ import annotations

import json
import re
import unicodedata
from dataclasses import dataclass
from datetime import datetime
from pathlib import Path
from typing import Annotated

from pydantic import AfterValidator, BaseModel, ConfigDict, Field, StringConstraints, ValidationError, model_validator
from pydantic_core import PydanticCustomError

from cook2ltl.errors import UserError
from cook2ltl.files import decoded, read_bytes
from cook2ltl.library import limits
from cook2ltl.library.effect import checked_effect
from cook2ltl.library.schema import SCHEMA_VERSION
from cook2ltl.library.store import LibraryEntry, Status
from cook2ltl.library.versions import Review, Version
from cook2ltl.paths import shown
from cook2ltl.reduce.body import is_empty, read_body
from cook2ltl.reduce.validation import CheckStatus

READABLE = range(2, SCHEMA_VERSION + 1)  # export files this cook2ltl reads
HINT = "export a library with `cook2ltl library export FILE` to see the format."


@dataclass(frozen=True)
class Exported:
    """One entry of an export file, with every version and review."""

    entry: LibraryEntry
    history: tuple[Version, ...]
    reviews: tuple[Review, ...]


def _fault(kind: str, message: str, **values: str) -> PydanticCustomError:
    return PydanticCustomError(kind, message, values)


def _plain(text: str) -> str:
    if any(unicodedata.category(character) == "Cc" for character in text):
        raise _fault("control", "has a control character")
    return text


def _filled(text: str) -> str:
    if not text.strip():
        raise _fault("empty", "is empty")
    return text


def _named(pattern: str, example: str):
    """A check that the text is a name of the form `pattern` (a regular expression), such as `example`."""
    form = re.compile(pattern)

    def check(text: str) -> str:
        if not form.fullmatch(text):
            raise _fault("name", "must be a name such as {example}", example=example)
        return text
    return check


def _time(text: str) -> str:
    try:
        datetime.fromisoformat(text)
    except ValueError:
        raise _fault("time", "must be an ISO 8601 time") from None
    return text


def _calls(text: str) -> str:
    """Calls one a line; empty for an entry with no plan."""
    _, unread = read_body(text)
    if unread:
        raise _fault("body", "has a line that is not a call: {line}", line=repr(unread[0][:80]))
    return text


Bounded = StringConstraints(max_length=limits.NAME_CHARS)
Name = Annotated[str, Bounded, AfterValidator(_filled), AfterValidator(_plain)]
Hash = Annotated[str, Bounded, AfterValidator(_plain)]
Verb = Annotated[str, Bounded, AfterValidator(_named(r"[a-z0-9][a-z0-9_]*", "boil or pick_up"))]
# A slot becomes a placeholder ($what, and $what2 for a second what): letters only, so the two never collide.
Slot = Annotated[str, Bounded, AfterValidator(_named(r"[a-z][a-z_]*", "what or where"))]
Placeholder = Annotated[str, Bounded, AfterValidator(_named(r"\$[a-z][a-z0-9_]*", "$what or $what2"))]
Time = Annotated[str, StringConstraints(max_length=64), AfterValidator(_time)]
Body = Annotated[str, StringConstraints(max_length=limits.BODY_BYTES), AfterValidator(_calls)]
Message = Annotated[str, StringConstraints(max_length=limits.MESSAGE_CHARS)]
Problems = Annotated[list[Message], Field(max_length=limits.PROBLEMS)]
Number = Annotated[int, Field(ge=1, le=limits.VERSION_NUMBER)]
# The file holds these as text: strict validation would ask for the enums themselves.
StatusName = Annotated[Status, Field(strict=False)]
Validation = Annotated[CheckStatus, Field(strict=False)]
STRICT = ConfigDict(strict=True, frozen=True, extra="ignore")  # fields of later versions are left for them


class VersionRecord(BaseModel):
    model_config = STRICT
    version: Number
    body: Body
    validation: Validation
    problems: Problems
    author: Name
    at: Time
    note: Message
    restores: Number | None = None

    @model_validator(mode="after")
    def _restores_an_earlier_one(self) -> VersionRecord:
        if self.restores is not None and self.restores >= self.version:
            raise _fault("restores", '"restores" must name an earlier version')
        return self


class ReviewRecord(BaseModel):
    model_config = STRICT
    version: Number
    status: StatusName
    reviewer: Name
    at: Time


class EntryRecord(BaseModel):
    model_config = STRICT
    primitives: Name
    verb: Verb
    signature: Annotated[list[Slot], Field(max_length=limits.SLOTS)]
    body: Body
    status: StatusName
    model: Name
    prompt_hash: Hash
    created: Time
    validation: Validation
    problems: Problems
    reviewed_by: Name | None = None
    reviewed_at: Time | None = None
    example: Annotated[dict[Placeholder, Name], Field(max_length=limits.SLOTS)]
    effect: Annotated[list[Annotated[str, Bounded]], Field(max_length=limits.ATOMS)] | None = None
    history: Annotated[list[VersionRecord], Field(min_length=1, max_length=limits.VERSIONS)]
    reviews: Annotated[list[ReviewRecord], Field(max_length=limits.VERSIONS)] = []  # none before schema 3

    @model_validator(mode="after")
    def _consistent(self) -> EntryRecord:
        numbers = [version.version for version in self.history]
        if numbers != sorted(set(numbers)) or self.history[-1].body != self.body:
            raise _fault("history", '"history" must go up in version numbers and end with the current body')
        stray = next((review.version for review in self.reviews if review.version not in numbers), None)
        if stray is not None:
            raise _fault("review", 'a review names version {version}, which is not in the entry\'s "history"',
                         version=str(stray))
        if self.status == "approved" and is_empty(self.body):
            raise _fault("approved", 'an entry with no plan (an empty "body") cannot be approved')
        return self


def read_export(path: Path) -> list[Exported]:
    """The entries of an export file, each checked field by field; any fault is a UserError naming it."""
    data = _json(path)
    where = shown(path)
    if not isinstance(data, dict) or "schema_version" not in data:
        raise UserError(f"{where} is not a library export: it has no \"schema_version\".", HINT)
    version = data["schema_version"]
    if isinstance(version, bool) or version not in READABLE:
        raise UserError(f"{where} has schema version {_brief(version)}; this cook2ltl reads versions "
                        f"{READABLE[0]} to {READABLE[-1]}.", "export it again with this cook2ltl, or upgrade cook2ltl.")
    entries = data.get("entries")
    if not isinstance(entries, list):
        raise UserError(f"{where}: \"entries\" must be a list of entries.", HINT)
    if len(entries) > limits.ENTRIES:
        raise UserError(f"{where} has {len(entries):,} entries; this cook2ltl imports at most {limits.ENTRIES:,}.",
                        "split the library into smaller exports.")
    return [_entry(raw, f"{where}: entry {number}") for number, raw in enumerate(entries, start=1)]


def _json(path: Path):
    raw = read_bytes(path, limits.EXPORT_BYTES, "export file", "give the path of an export file.",
                     "split the library into smaller exports.")
    text = decoded(raw, f"The export file {shown(path)}")
    try:
        data = json.loads(text)
        json.dumps(data, ensure_ascii=False).encode("utf-8")  # a \udcff escape is JSON but not storable text
    except json.JSONDecodeError as error:
        raise UserError(f"{shown(path)} is not valid JSON: {error.msg} at line {error.lineno}, column {error.colno}.",
                        HINT) from error
    except UnicodeEncodeError as error:
        raise UserError(f"{shown(path)} is not a library export: it has text that is not Unicode "
                        f"({error.object[error.start:error.end]!r}, a lone surrogate).", HINT) from error
    except RecursionError as error:
        raise UserError(f"{shown(path)} is not a library export: its JSON nests too deeply.", HINT) from error
    except ValueError as error:  # an integer of thousands of digits
        raise UserError(f"{shown(path)} is not a library export: {error}.", HINT) from error
    return data


def _entry(raw, where: str) -> Exported:
    if not isinstance(raw, dict):
        raise UserError(f"{where} is not a JSON object.", HINT)
    try:
        record = EntryRecord.model_validate(raw)
    except ValidationError as error:
        raise UserError(f"{where}{_described(error.errors(include_url=False)[0])}.", HINT) from None
    versions = tuple(Version(0, v.version, v.body, v.validation, tuple(v.problems), v.author, v.at, v.note,
                             v.restores) for v in record.history)
    entry = LibraryEntry(
        id=0, primitives=record.primitives, verb=record.verb, signature=tuple(record.signature), body=record.body,
        status=Status(record.status), model=record.model, prompt_hash=record.prompt_hash, created=record.created,
        validation=record.validation, problems=tuple(record.problems), reviewed_by=record.reviewed_by,
        reviewed_at=record.reviewed_at, example=tuple(record.example.items()), version=versions[-1].version,
        effect=checked_effect(record.effect, f'{where}: "effect"'),
    )
    return Exported(entry, versions, tuple(Review(0, r.version, r.status, r.reviewer, r.at) for r in record.reviews))


SAID = {"missing": "is missing", "model_type": "must be a JSON object", "dict_type": "must be a JSON object",
        "list_type": "must be a list", "string_type": "must be a string", "int_type": "must be a whole number",
        "literal_error": "must be one of {expected}", "enum": "must be one of {expected}",
        "none_required": "must be null",
        "too_short": "must have at least {min_length} item(s)", "too_long": "has more than {max_length:,} items",
        "string_too_long": "is longer than {max_length:,} characters", "less_than_equal": "must be at most {le:,}",
        "greater_than_equal": "must be at least {ge:,}"}


def _described(error: dict) -> str:
    """", "history" item 2, "version": must be a whole number, not "7"": where in the entry, and what is wrong."""
    field = ""
    for step in error["loc"]:
        if isinstance(step, int):
            field += f" item {step + 1}"
        elif step != "[key]":  # pydantic's mark for a key of an object (the key is the step before)
            field += f", {json.dumps(step, ensure_ascii=False)}"
    said = SAID.get(error["type"], error["msg"]).format(**error.get("ctx", {}))
    shown_input = "" if error["type"] in WITHOUT_INPUT else f", not {_brief(error['input'])}"
    return f"{field}: {said}{shown_input}" if field else f": {said}"


# Faults whose input says nothing more (a missing or empty field), is too long to show, or is the whole entry.
WITHOUT_INPUT = ("missing", "empty", "too_short", "too_long", "string_too_long", "body", "history", "review",
                 "approved", "restores")


def _brief(value) -> str:
    """A JSON value as a message shows it: short, on one line."""
    text = json.dumps(value, ensure_ascii=False)
    return text if len(text) <= 60 else f"{text[:57]}…"
