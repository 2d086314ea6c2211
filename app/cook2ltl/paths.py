"""Where cook2ltl reads and writes: one module, every path overridable by an environment variable."""

from __future__ import annotations

import os
from pathlib import Path

from platformdirs import user_cache_dir, user_config_dir, user_data_dir

APP = "cook2ltl"
# The package lives in app/cook2ltl/, so the project root is two levels up.
PROJECT_ROOT = Path(__file__).resolve().parents[2]


def _env_path(var: str, default: Path) -> Path:
    value = os.environ.get(var)
    return Path(value).expanduser() if value else default


def models_dir() -> Path:
    """The manifest folder (models/models.toml) and the links to cached weights."""
    return _env_path("COOK2LTL_MODELS_DIR", PROJECT_ROOT / "models")


def model_cache_dir() -> Path:
    """Per-user store of weights, shared by every clone so nothing is fetched or trained twice."""
    return _env_path("COOK2LTL_MODEL_CACHE", Path(user_cache_dir(APP)) / "models")


def assets_dir() -> Path:
    return _env_path("COOK2LTL_ASSETS", PROJECT_ROOT / "assets")


def config_file() -> Path:
    return _env_path("COOK2LTL_CONFIG", Path(user_config_dir(APP)) / "config.toml")


def data_dir() -> Path:
    return _env_path("COOK2LTL_DATA", Path(user_data_dir(APP)))


def shared_data_dir() -> Path:
    """The paper's annotated data, used for training and benchmarks (not needed at run time)."""
    return _env_path("COOK2LTL_SHARED_DATA", PROJECT_ROOT.parent / "shared" / "data")


def library_file() -> Path:
    """The action library 𝔸 (SQLite), shared by every run of every recipe."""
    return _env_path("COOK2LTL_LIBRARY", data_dir() / "library.sqlite")
