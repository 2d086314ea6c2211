"""Reading the settings file: an absent one gives the defaults; the schema is loaded only when a file exists,
so a start without one stays fast."""

from __future__ import annotations

from pathlib import Path

from cook2ltl import files, paths
from cook2ltl.domain.settings import Settings

SETTINGS_BYTES = 1_000_000  # a settings file is a few lines


def load_settings(path: Path | None = None) -> Settings:
    """The settings file's (an absent one: the defaults); anything else in it than what the README describes,
    or a value out of its bounds, is a UserError naming the key."""
    path = paths.config_file() if path is None else paths.user_path(path, "The settings file")
    try:
        raw = files.read_toml(path, SETTINGS_BYTES, "settings file", "give COOK2LTL_CONFIG a TOML file of settings.")
    except files.MissingFile:
        return Settings()
    # startup: pydantic (~100 ms) loads only when a settings file exists
    from cook2ltl.domain.settings_schema import settings_from

    return settings_from(raw, path)
