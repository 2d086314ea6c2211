"""Reading a recipe from a file or stdin, with a clear message for anything that is not text."""

from __future__ import annotations

import sys
from pathlib import Path

from cook2ltl.errors import UserError

MAX_RECIPE_BYTES = 1_000_000


def read_recipe(source: str) -> str:
    if source == "-":
        data = sys.stdin.buffer.read(MAX_RECIPE_BYTES + 1)
        name = "standard input"
    else:
        path = Path(source)
        if not path.is_file():
            raise UserError(f"No recipe file at {path}.", "give a text file, or - to read standard input.")
        with path.open("rb") as handle:
            data = handle.read(MAX_RECIPE_BYTES + 1)
        name = str(path)
    if len(data) > MAX_RECIPE_BYTES:
        raise UserError(f"{name} is larger than {MAX_RECIPE_BYTES:,} bytes.", "split the recipe into smaller files.")
    if b"\x00" in data:
        raise UserError(f"{name} looks binary, not a recipe.", "give a UTF-8 text file.")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise UserError(f"{name} is not UTF-8 text (byte {error.start}).", "convert it with `iconv -t utf-8`.") from error
