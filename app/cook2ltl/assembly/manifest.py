"""models/models.toml as frozen records, and where each model's files are."""

from __future__ import annotations

import hashlib
import importlib.util
import tomllib
from dataclasses import dataclass
from enum import StrEnum
from pathlib import Path

from cook2ltl import paths
from cook2ltl.errors import UserError

MANIFEST = "models.toml"
STAMP = ".cook2ltl-sha256"  # written beside a trained model once it is complete


class ModelSource(StrEnum):
    PIP = "pip"
    WHEEL = "wheel"
    SPLIT_WHEELS = "split-wheels"
    TRAIN = "train"


class ModelState(StrEnum):
    READY = "ready"
    MISSING = "missing"
    CORRUPT = "corrupt"


@dataclass(frozen=True)
class ModelEntry:
    name: str
    role: str
    source: ModelSource
    licence: str
    upstream: str = ""
    sha256: str = ""
    package: str = ""
    version: str = ""
    module: str = ""
    check: str = ""
    member: str = ""
    file: str = ""
    parts: int = 0
    recipe: str = ""
    encoder: str = ""
    data: str = ""

    def origin(self) -> str:
        if self.source == ModelSource.TRAIN:
            return "trained here"
        if self.source == ModelSource.SPLIT_WHEELS:
            return f"PyPI {self.package.format(n='1..' + str(self.parts))}=={self.version}"
        return f"PyPI {self.package}=={self.version}"


def load_manifest(folder: Path | None = None) -> dict[str, ModelEntry]:
    path = (folder or paths.models_dir()) / MANIFEST
    try:
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
    except (FileNotFoundError, NotADirectoryError) as error:
        raise UserError(f"No model manifest at {path}.", "set COOK2LTL_MODELS_DIR to the project's models/ folder.") from error
    except (OSError, UnicodeDecodeError) as error:
        raise UserError(f"Cannot read the model manifest {path}: {error}") from error
    except tomllib.TOMLDecodeError as error:
        raise UserError(f"{path} is not valid TOML: {error}") from error
    try:
        return {name: ModelEntry(name=name, **fields) for name, fields in raw.items()}
    except TypeError as error:
        raise UserError(f"{path}: {error}") from error


def sha256_of(path: Path) -> str:
    digest = hashlib.sha256()
    with path.open("rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def model_path(entry: ModelEntry) -> Path | None:
    """Where the model's files are once provisioned (a file, a package folder, or a checkpoint folder)."""
    if entry.source == ModelSource.PIP:
        spec = importlib.util.find_spec(entry.module)
        return Path(spec.origin).parent if spec and spec.origin else None
    if entry.source == ModelSource.TRAIN:
        return trained_path(entry)
    return paths.model_cache_dir() / entry.name / entry.file


def trained_path(entry: ModelEntry) -> Path:
    """Keyed by a fingerprint of data and recipe, so changing either retrains and nothing is reused stale."""
    # startup: the training code (~6 ms) loads when a trained model is located, not with the app or --help
    from cook2ltl.parse.training.train import TrainConfig, fingerprint

    data = paths.models_dir() / entry.data
    if paths.inside_package(paths.models_dir()):  # a wheel has no training data: the checkpoint a checkout trained
        trained = sorted(paths.model_cache_dir().glob(f"{entry.name}-{'[0-9a-f]' * 12}/{STAMP}"),
                         key=lambda stamp: stamp.stat().st_mtime)
        return trained[-1].parent if trained else paths.model_cache_dir() / f"{entry.name}-(not trained)"
    return paths.model_cache_dir() / f"{entry.name}-{fingerprint(data, TrainConfig())[:12]}"


def checked_file(entry: ModelEntry, where: Path) -> Path:
    return where / entry.check if entry.source == ModelSource.PIP else where


def state_of(entry: ModelEntry, verify_hash: bool = True) -> ModelState:
    where = model_path(entry)
    if where is None or not where.exists():
        return ModelState.MISSING
    if entry.source == ModelSource.TRAIN:
        stamp = where / STAMP
        if not stamp.exists():
            return ModelState.MISSING  # an interrupted training leaves no stamp and is redone
        expected = stamp.read_text().strip()
        return ModelState.READY if not verify_hash or checkpoint_digest(where) == expected else ModelState.CORRUPT
    target = checked_file(entry, where)
    if not target.exists():
        return ModelState.MISSING
    return ModelState.READY if not verify_hash or sha256_of(target) == entry.sha256 else ModelState.CORRUPT


def checkpoint_digest(folder: Path) -> str:
    """One digest over every file of a checkpoint folder but the stamp itself."""
    digest = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file() and p.name != STAMP):
        digest.update(path.relative_to(folder).as_posix().encode())
        digest.update(sha256_of(path).encode())
    return digest.hexdigest()
