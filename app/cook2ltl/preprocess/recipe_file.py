"""Reading a recipe from a file or stdin, bounded by [limits] recipe_bytes, with a clear message for anything
that is not text."""

from __future__ import annotations

from cook2ltl import files, paths
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.errors import UserError

FILE_HINT = "give a text file, or - to read standard input."
TOO_LARGE_HINT = "split the recipe into smaller files, or raise [limits] recipe_bytes in the settings file."


def read_recipe(source: str, max_bytes: int | None = None) -> str:
    """The recipe's text; `max_bytes` defaults to the settings' [limits] recipe_bytes."""
    if max_bytes is None:
        max_bytes = load_settings().limits.recipe_bytes
    if source == "-":
        data, name = files.read_stdin(max_bytes, TOO_LARGE_HINT), "standard input"
    else:
        path = paths.user_path(source, "The recipe file")
        data, name = files.read_bytes(path, max_bytes, "recipe file", FILE_HINT, TOO_LARGE_HINT), paths.shown(path)
    if b"\x00" in data:
        raise UserError(f"{name} looks binary, not a recipe.", "give a UTF-8 text file.")
    return files.decoded(data, name)
