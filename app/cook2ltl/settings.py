"""User settings from one TOML file ($COOK2LTL_CONFIG or the platform's config folder).

    [ner]
    checkpoint = "/labs/models/gliner-multi"   # any GLiNER checkpoint folder; default: the one trained here
    threshold = 0.5
    [ner.labels]                               # that checkpoint's names for the six categories
    VERB = "action"
    WHAT = "ingredient or utensil"
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from cook2ltl import paths
from cook2ltl.domain import Label
from cook2ltl.errors import UserError


@dataclass(frozen=True)
class NerSettings:
    checkpoint: Path | None = None
    labels: dict[Label, str] = field(default_factory=dict)
    threshold: float = 0.5


@dataclass(frozen=True)
class Settings:
    ner: NerSettings = NerSettings()
    source: Path | None = None


def load_settings(path: Path | None = None) -> Settings:
    path = path or paths.config_file()
    if not path.exists():
        return Settings()
    try:
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise UserError(f"Settings file {path} is not valid TOML: {error}", "fix it or set COOK2LTL_CONFIG.") from error
    ner = raw.get("ner", {})
    try:
        labels = {Label(key.upper()): str(value) for key, value in ner.get("labels", {}).items()}
        checkpoint = Path(ner["checkpoint"]).expanduser() if ner.get("checkpoint") else None
        threshold = float(ner.get("threshold", NerSettings.threshold))
    except (ValueError, TypeError) as error:
        raise UserError(f"{path}: bad [ner] setting: {error}",
                        f"labels are keyed by {', '.join(Label)}; threshold is a number.") from error
    return Settings(ner=NerSettings(checkpoint, labels, threshold), source=path)
