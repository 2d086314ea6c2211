"""Files the library commands open or write: what is at a path (the system's refusals as UserErrors), and a
write that leaves the old file or the new one, never half of either."""

from __future__ import annotations

import os
import secrets
import stat
from pathlib import Path

from cook2ltl.errors import UserError
from cook2ltl.paths import shown


def reason(error: OSError | ValueError) -> str:
    return getattr(error, "strerror", None) or str(error)


def file_status(path: Path, what: str) -> os.stat_result | None:
    """os.stat of `path` (following links); None when nothing is there. A path the system refuses outright
    (a name too long, a file where a folder should be, a NUL byte) is a UserError naming `what`."""
    try:
        return os.stat(path)
    except FileNotFoundError:
        return None
    except (OSError, ValueError) as error:
        raise UserError(f"Cannot use {shown(path)} as {what}: {reason(error)}.",
                        "check the path: every folder on the way must exist and be yours to open.") from error


def replace_whole(path: Path, data: bytes, hint: str) -> None:
    """Write `data` to `path` so that it holds the old file or the new one, whatever happens: a temporary file in
    the same folder, flushed to the disk, then renamed over the target. A link is followed (the link stays), and
    only a regular file is replaced: never a device, a folder or a FIFO."""
    target = Path(os.path.realpath(path))
    found = file_status(target, "the file to write")
    if found is not None and not stat.S_ISREG(found.st_mode):
        raise UserError(f"Cannot write {shown(path)}: it is {_kind(found.st_mode)}, not a regular file.", hint)
    temporary = target.with_name(f".{target.name[:64]}.{secrets.token_hex(4)}.tmp")
    try:
        handle = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_CLOEXEC, 0o666)  # umask applies
    except (OSError, ValueError) as error:
        raise UserError(f"Cannot write {shown(path)}: {reason(error)}.", hint) from error
    try:
        with os.fdopen(handle, "wb") as file:
            file.write(data)
            file.flush()
            os.fsync(file.fileno())
            if found is not None:
                os.fchmod(file.fileno(), stat.S_IMODE(found.st_mode))  # the file keeps who may read it
        os.replace(temporary, target)
        _sync_folder(target.parent)
    except BaseException as error:
        temporary.unlink(missing_ok=True)
        if isinstance(error, OSError):
            raise UserError(f"Cannot write {shown(path)}: {reason(error)}.", hint) from error
        raise


def _sync_folder(folder: Path) -> None:
    """Make the rename itself durable (a crash right after it keeps the new name)."""
    handle = os.open(folder, os.O_RDONLY | os.O_CLOEXEC)
    try:
        os.fsync(handle)
    finally:
        os.close(handle)


def _kind(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISFIFO(mode):
        return "a FIFO"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    return "a socket" if stat.S_ISSOCK(mode) else "not a file"
