"""Where cook2ltl reads and writes: one module, every path overridable by an environment variable; and the one
check every path a user gives goes through (an option, an argument, a setting or an environment variable)."""

from __future__ import annotations

import os
from importlib import resources
from pathlib import Path

from platformdirs import user_cache_dir, user_config_dir, user_data_dir

from cook2ltl.errors import UserError

APP = "cook2ltl"
# In a checkout (PYTHONPATH=app, or the editable install) the package lives in app/cook2ltl/, so the project root is
# two levels up, and the run-time files are the checkout's assets/ and models/models.toml. An installed wheel
# carries its own copies of both inside the package, as cook2ltl/_assets/ and cook2ltl/_models/ (pyproject.toml).
PACKAGE = Path(__file__).resolve().parent
PROJECT_ROOT = PACKAGE.parents[1]
IN_CHECKOUT = PACKAGE.parent.name == "app" and (PROJECT_ROOT / "pyproject.toml").is_file()
MAX_PATH_BYTES = 4096  # Linux's PATH_MAX: longer fails in every call with ENAMETOOLONG
MAX_NAME_BYTES = 255  # NAME_MAX: the longest one folder or file name may be
SHOWN_CHARACTERS = 160  # a path longer than this is shown with its middle left out


def user_path(value: str | os.PathLike, what: str) -> Path:
    """`value` as a path, `~` expanded, or a UserError that names `what` (e.g. "--library"): no NUL byte,
    UTF-8, not empty, and short enough for the system to open."""
    text = os.fspath(value)
    hint = "give the path of a file or folder, e.g. ~/robot/primitives.toml."
    if isinstance(text, bytes) or "\x00" in text:
        raise UserError(f"{what} {shown(text)} is not a path (it holds a NUL byte or raw bytes).", hint)
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:  # bytes that are not UTF-8, from argv or the environment (or a lone surrogate)
        raise UserError(f"{what} {shown(text)} is not UTF-8 text.", hint) from None
    if not text.strip():
        raise UserError(f"{what} is empty.", hint)
    try:
        path = Path(text).expanduser()
    except RuntimeError:  # ~name of no such user, or no home folder to expand ~ to
        raise UserError(f"{what} {shown(text)}: cannot tell which home folder ~ means.",
                        "write the path out in full.") from None
    encoded = os.fsencode(path)
    if len(encoded) >= MAX_PATH_BYTES or any(len(name) > MAX_NAME_BYTES for name in encoded.split(b"/")):
        raise UserError(f"{what} {shown(text)} is too long for a path ({MAX_PATH_BYTES - 1:,} bytes at most, "
                        f"{MAX_NAME_BYTES} for each name in it).", hint)
    return path


def shown(path: str | bytes | os.PathLike) -> str:
    """A path as a message shows it: on one line (escapes for control characters), its middle left out when long."""
    text = os.fsdecode(path)
    text = text if text.isprintable() else repr(text)[1:-1]
    if len(text) <= SHOWN_CHARACTERS:
        return text
    half = SHOWN_CHARACTERS // 2
    return f"{text[:half]}…{text[-half:]}"


def _env_path(var: str, default: Path) -> Path:
    value = os.environ.get(var)
    return user_path(value, f"${var}") if value else default


def _run_time_files(var: str, folder: str) -> Path:
    """$var if set; else the checkout's folder when running from one; else the copy the wheel installed (wheels
    are installed unpacked, so it is a real folder)."""
    return _env_path(var, PROJECT_ROOT / folder if IN_CHECKOUT else Path(resources.files(APP) / f"_{folder}"))


def inside_package(path: Path) -> bool:
    """Whether `path` is in the installed package (a wheel's copy of assets/ or models/): cook2ltl never writes
    there, and it holds no training data."""
    return path.resolve().is_relative_to(PACKAGE)


def models_dir() -> Path:
    """The manifest folder (models/models.toml), in a checkout also the training data and the links to cached
    weights (the weights themselves are always in model_cache_dir())."""
    return _run_time_files("COOK2LTL_MODELS_DIR", "models")


def model_cache_dir() -> Path:
    """Per-user store of weights, shared by every clone so nothing is fetched or trained twice."""
    return _env_path("COOK2LTL_MODEL_CACHE", Path(user_cache_dir(APP)) / "models")


def assets_dir() -> Path:
    """Primitive sets, PDDL domains, prompts, kitchens, tasks, the verb-effect table and the demo recipe."""
    return _run_time_files("COOK2LTL_ASSETS", "assets")


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


def output_folder(value: str | os.PathLike, what: str) -> Path:
    """The folder a command will write into, made now, so a path that cannot be one is refused before a long
    run rather than after it."""
    path = user_path(value, what)
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as error:  # a file there, a file on the way, no permission, a read-only disk
        raise UserError(f"{what} {shown(path)} cannot be a folder to write into: {error.strerror or error}.",
                        "give a folder you may write to, or one that does not exist yet.") from None
    return path
