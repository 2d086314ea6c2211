"""Typed values from the TOML files a user writes (settings, primitive sets, kitchens): pydantic models that
refuse what does not fit (no 0.5 read as 0, no true read as 1, no unknown key, no unbounded number or list),
and a one-line error naming the file, the key and what it must be.

Every field says what it must be in its `description` ("a whole number from 1 to 100,000"); the error
message is built from the description of the innermost described type on the failing key's way."""

from __future__ import annotations

import reprlib
import types
import typing
from pathlib import Path
from typing import Annotated, Any, TypeVar

from pydantic import BaseModel, ConfigDict, Field, StringConstraints, ValidationError
from pydantic.fields import FieldInfo

from cook2ltl.errors import UserError
from cook2ltl.paths import shown

MAX_TEXT = 200  # a label, a key binding, a set's name
MAX_PATH_TEXT = 4096

_PRINTABLE = r"[^\x00-\x1f\x7f-\x9f]"  # no control character, so a value stays on its line
T = TypeVar("T", bound="Table")
_SHORT = reprlib.Repr()  # a value as an error shows it: short, on one line
_SHORT.maxstring = _SHORT.maxother = 60
_SHORT.maxlist, _SHORT.maxdict, _SHORT.maxlevel = 5, 4, 3


class Table(BaseModel):
    """A TOML table: its keys are the fields; any other key is an error; values are never coerced."""

    model_config = ConfigDict(extra="forbid", frozen=True, strict=True)


Identifier = Annotated[str, StringConstraints(pattern=r"^[a-z][a-z0-9_]*$", max_length=64),
                       Field(description="a lower-case identifier such as pick_up or baking_pan (a-z, 0-9 and _)")]
PddlName = Annotated[str, StringConstraints(pattern=r"^[a-z][a-z0-9_-]*$", max_length=64),
                     Field(description="a PDDL name such as filled-with (a-z, 0-9, _ and -)")]
PathText = Annotated[str, StringConstraints(min_length=1, max_length=MAX_PATH_TEXT)]
FileName = Annotated[PathText, Field(description="the path of a file")]
Text = Annotated[str, StringConstraints(pattern=rf"^{_PRINTABLE}*[^\s\x00-\x1f\x7f-\x9f]{_PRINTABLE}*$",
                                        max_length=MAX_TEXT),
                 Field(description=f"text on one line, not blank, at most {MAX_TEXT} characters")]


def whole_number(default: int, low: int, high: int) -> Any:
    return Field(default, ge=low, le=high, description=f"a whole number from {low:,} to {high:,}")


def number(default: float, low: float, high: float) -> Any:
    return Field(default, ge=low, le=high, allow_inf_nan=False, description=f"a number from {low:g} to {high:g}")


def flag(default: bool) -> Any:
    return Field(default, description="true or false")


def validated(model: type[T], raw: dict, path: Path, hint: str) -> T:
    try:
        return model.model_validate(raw)
    except ValidationError as error:
        raise UserError(f"{shown(path)}: {problem(model, error.errors(include_url=False)[0])}.", hint) from None


def problem(model: type[Table], error: dict) -> str:
    """One of pydantic's errors in the file's terms: where (as TOML writes it), what it must be, what it is."""
    loc = error["loc"]
    tables, keys, table, described = _place(model, loc)
    header = f"[{'.'.join(tables)}]" if tables else ""
    where = " ".join(filter(None, (header, _dotted(keys))))
    value = _value(error["input"])
    if error["type"] == "extra_forbidden":
        return f"unknown key {where} ({header or 'the file'} has {', '.join(table.model_fields)})"
    if error["type"] == "missing":
        return f"{where} is missing: it must be {described or 'given'}"
    if loc and loc[-1] == "[key]":  # pydantic's mark of a dict's key, after the key
        owner = " ".join(filter(None, (header, _dotted(keys[:-1]))))
        return f"{owner} has the key {value}, which must be {described}"
    return f"{where} must be {described}, not {value}" if described else f"{where}: {error['msg'].lower()}"


def _place(model: type[Table], loc: tuple) -> tuple[list[str], list, type[Table], str | None]:
    """The tables on the way to the failing key (a model's or a dict's), the keys after them, the last model,
    and the innermost description on the way."""
    tables: list[str] = []
    keys: list = []
    table, annotation, described = model, model, None
    for index, step in enumerate(loc):
        base, metadata = _unwrapped(annotation)
        described = _description(metadata) or described
        if step == "[key]":
            continue
        if _is_table(base):
            table, field = base, base.model_fields.get(step)
            if field is None:  # an unknown key
                return tables, [*keys, step], table, described
            annotation, described = field.annotation, field.description or described
        elif typing.get_origin(base) is dict:
            annotation = typing.get_args(base)[0 if loc[index + 1:index + 2] == ("[key]",) else 1]
        elif typing.get_origin(base) is list:
            annotation = typing.get_args(base)[0]
        inner = _unwrapped(annotation)[0]
        opens_table = (_is_table(inner) or typing.get_origin(inner) is dict) and index < len(loc) - 1
        (tables if opens_table and not keys else keys).append(step)
    return tables, keys, table, _description(_unwrapped(annotation)[1]) or described


def _value(value: Any) -> str:
    """A value as TOML writes it, cut short."""
    return str(value).lower() if isinstance(value, bool) else _SHORT.repr(value)


def _unwrapped(annotation: Any) -> tuple[Any, list]:
    """The type under Annotated and `| None`, and the metadata Annotated gave it."""
    metadata: list = []
    while True:
        if typing.get_origin(annotation) is Annotated:
            metadata = [*annotation.__metadata__, *metadata]
            annotation = annotation.__origin__
        elif isinstance(annotation, types.UnionType) or typing.get_origin(annotation) is typing.Union:
            annotation = next(a for a in typing.get_args(annotation) if a is not type(None))
        else:
            return annotation, metadata


def _description(metadata: list) -> str | None:
    return next((m.description for m in reversed(metadata) if isinstance(m, FieldInfo) and m.description), None)


def _is_table(annotation: Any) -> bool:
    return isinstance(annotation, type) and issubclass(annotation, Table)


def _dotted(keys: list) -> str:
    """Keys as TOML writes them after a table header: put[0], a.b, 'two words'."""
    text = ""
    for key in keys:
        if isinstance(key, int):
            text += f"[{key}]"
        elif key != "[key]":
            name = key if key.isascii() and key.replace("_", "").replace("-", "").isalnum() else _SHORT.repr(key)
            text += f".{name}" if text else name
    return text
