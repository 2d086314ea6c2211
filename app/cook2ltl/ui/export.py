"""A translation written to a file: JSON (the CLI's `--json` form, kitchen checks included) or the CLI's text form
without colours, both as the CLI prints them (control characters as escapes)."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from cook2ltl.errors import UserError
from cook2ltl.pipeline.report import show
from cook2ltl.pipeline.serialize import translation_json
from cook2ltl.text_safety import json_text, terminal

if TYPE_CHECKING:
    from cook2ltl.pipeline.records import Translation


def write_translation(translation: Translation, path: Path) -> None:
    try:
        with path.open("w", encoding="utf-8") as handle:
            if path.suffix == ".json":
                handle.write(json_text(translation_json(translation)) + "\n")
            else:
                show(translation, terminal(file=handle, width=120, no_color=True, highlight=False, soft_wrap=True))
    except OSError as error:
        raise UserError(f"Cannot write {path}: {error.strerror}.", "choose a writable folder.") from error
