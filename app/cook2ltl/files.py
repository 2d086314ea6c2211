"""Reading the files a user names, bounded: at most so many bytes of a regular file, decoded as UTF-8, or a
clear UserError naming the file. /dev/zero, a FIFO, a socket or a folder is refused before a byte is read, so
no such path can fill the memory or wait forever."""

from __future__ import annotations

import os
import stat
import sys
import tomllib
from pathlib import Path

from cook2ltl.errors import UserError
from cook2ltl.paths import shown

UTF8_HINT = "save it as UTF-8 text (e.g. with `iconv -t utf-8`)."


class MissingFile(UserError):
    """No file at the path: for a settings file that is optional, the defaults."""


def read_bytes(path: Path, limit: int, what: str, hint: str, too_large_hint: str = "") -> bytes:
    """The bytes of the regular file `path`, refused when more than `limit` (limit + 1 are read to tell).
    `hint` says what to give instead; `too_large_hint` how to give a larger file (default: `hint`)."""
    try:
        _require_regular(os.stat(path), path, what, hint)
        # Non-blocking: a FIFO put there since the check is not waited on; fstat then refuses it.
        with open(os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC), "rb") as handle:
            _require_regular(os.fstat(handle.fileno()), path, what, hint)
            data = handle.read(limit + 1)
    except FileNotFoundError:
        raise MissingFile(f"No {what} at {shown(path)}.", hint) from None
    except (OSError, ValueError) as error:  # too long, not a folder on the way, no permission, a loop, a NUL
        reason = error.strerror if isinstance(error, OSError) and error.strerror else str(error)
        raise UserError(f"Cannot read the {what} {shown(path)}: {reason}.", hint) from None
    return within(data, limit, f"The {what} {shown(path)}", too_large_hint or hint)


def read_text(path: Path, limit: int, what: str, hint: str) -> str:
    return decoded(read_bytes(path, limit, what, hint), f"The {what} {shown(path)}")


def read_stdin(limit: int, hint: str) -> bytes:
    """Standard input, up to `limit` bytes: whatever is piped in (/dev/zero too) is read no further."""
    return within(sys.stdin.buffer.read(limit + 1), limit, "Standard input", hint)


def read_toml(path: Path, limit: int, what: str, hint: str) -> dict:
    """The TOML file as a dict: its size bounded, its syntax, number sizes and nesting depth checked."""
    text = read_text(path, limit, what, hint)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise UserError(f"The {what} {shown(path)} is not valid TOML: {error}", hint) from None
    except ValueError:  # an integer of thousands of digits, past Python's limit on converting one
        raise UserError(f"The {what} {shown(path)} is not valid TOML: it holds a number too long to read.",
                        hint) from None
    except RecursionError:
        raise UserError(f"The {what} {shown(path)} is not valid TOML: it is nested too deeply.", hint) from None


def is_regular_file(path: Path) -> bool:
    """Whether `path` names a regular file; False too for a path the system refuses (too long, no permission)."""
    try:
        return stat.S_ISREG(os.stat(path).st_mode)
    except (OSError, ValueError):
        return False


def within(data: bytes, limit: int, name: str, hint: str) -> bytes:
    if len(data) > limit:
        raise UserError(f"{name} is larger than the limit of {limit:,} bytes.", hint)
    return data


def decoded(data: bytes, name: str) -> str:
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise UserError(f"{name} is not UTF-8 text (byte {error.start}).", UTF8_HINT) from None


def _require_regular(status: os.stat_result, path: Path, what: str, hint: str) -> None:
    if stat.S_ISDIR(status.st_mode):
        raise UserError(f"Cannot read the {what} {shown(path)}: it is a folder.", hint)
    if not stat.S_ISREG(status.st_mode):
        raise UserError(f"Cannot read the {what} {shown(path)}: it is not a regular file (a device, a pipe or a "
                        "socket).", hint)
