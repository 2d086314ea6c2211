"""Reading a recipe from a file or stdin, with a clear message for anything that is not text."""

from __future__ import annotations

import sys
from pathlib import Path

from cook2ltl.errors import UserError


def read_recipe(source: str, max_bytes: int | None = None) -> str:
    """The recipe's text; `max_bytes` defaults to the settings' [limits] recipe_bytes."""
    if max_bytes is None:
        from cook2ltl.settings import load_settings

        max_bytes = load_settings().limits.recipe_bytes
    if source == "-":
        data = sys.stdin.buffer.read(max_bytes + 1)
        name = "standard input"
    else:
        path = Path(source)
        if not path.is_file():
            raise UserError(f"No recipe file at {path}.", "give a text file, or - to read standard input.")
        try:
            with path.open("rb") as handle:
                data = handle.read(max_bytes + 1)
        except OSError as error:
            raise UserError(f"Cannot read {path}: {error.strerror}.", "check the file's permissions.") from error
        name = str(path)
    if len(data) > max_bytes:
        raise UserError(f"{name} is larger than the limit of {max_bytes:,} bytes.",
                        "split the recipe into smaller files, or raise [limits] recipe_bytes in the settings file.")
    if b"\x00" in data:
        raise UserError(f"{name} looks binary, not a recipe.", "give a UTF-8 text file.")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise UserError(f"{name} is not UTF-8 text (byte {error.start}).", "convert it with `iconv -t utf-8`.") from error
