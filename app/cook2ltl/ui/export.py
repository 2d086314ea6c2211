"""A translation written to a file: JSON (the CLI's `--json` form, kitchen checks included) or the CLI's text form
without colours."""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING

from cook2ltl.errors import UserError

if TYPE_CHECKING:
    from cook2ltl.pipeline import Translation


def write_translation(translation: Translation, path: Path) -> None:
    from rich.console import Console

    from cook2ltl.cli.translate_command import show, with_validation
    from cook2ltl.translate.serialize import translation_json

    try:
        with path.open("w", encoding="utf-8") as handle:
            if path.suffix == ".json":
                json.dump(with_validation(translation_json(translation), translation), handle, ensure_ascii=False,
                          indent=2)
                handle.write("\n")
            else:
                show(translation, Console(file=handle, width=120, no_color=True, highlight=False, soft_wrap=True))
    except OSError as error:
        raise UserError(f"Cannot write {path}: {error.strerror}.", "choose a writable folder.") from error
