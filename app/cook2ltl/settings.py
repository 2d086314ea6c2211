"""User settings from one TOML file ($COOK2LTL_CONFIG or the platform's config folder).

    [ner]
    checkpoint = "/labs/models/gliner-multi"   # any GLiNER checkpoint folder; default: the one trained here
    threshold = 0.5
    [ner.labels]                               # that checkpoint's names for the six categories
    VERB = "action"
    WHAT = "ingredient or utensil"
    [limits]                                   # what one run accepts; larger inputs are refused with a message
    recipe_bytes = 200000
    steps = 500
    llm_seconds = 120                          # wall-clock bound of one reduction by the language model
    [translate]                                # the app's Translate screen
    primitives = ["~/robot/primitives.toml"]   # your robots' primitive sets, offered beside recipe and ai2thor
    repairs = 2                                # times a plan the kitchen refuses goes back to the model
    ground = true                              # plans decoded, checked and completed in the world model
    [keymap]                                   # the app's keys: binding id = keys (a wrong id is named)
    "translate.run" = "ctrl+enter"
    "library.approve" = "y,a"
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
class Limits:
    """Bounds on one run: a recipe is a page or a few, not a book, and no model call may hang a batch."""

    recipe_bytes: int = 200_000  # the 50 paper recipes are under 2 kB each
    steps: int = 500
    llm_seconds: float = 120.0  # a reduction takes 1-15 s on 2 cores (README)


@dataclass(frozen=True)
class TranslateSettings:
    primitives: tuple[Path, ...] = ()  # TOML primitive sets beside the built-in ones
    repairs: int = 2
    ground: bool = True  # check and complete every plan in the primitive set's world model


@dataclass(frozen=True)
class Settings:
    ner: NerSettings = NerSettings()
    limits: Limits = Limits()
    translate: TranslateSettings = TranslateSettings()
    keymap: dict[str, str] = field(default_factory=dict)  # binding id -> keys; the app checks the ids
    source: Path | None = None


def load_settings(path: Path | None = None) -> Settings:
    path = path or paths.config_file()
    if not path.exists():
        return Settings()
    try:
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise UserError(f"Settings file {path} is not valid TOML: {error}", "fix it or set COOK2LTL_CONFIG.") from error
    except OSError as error:  # a folder, a file we may not read
        raise UserError(f"Cannot read the settings file {path}: {error.strerror or error}.",
                        "give COOK2LTL_CONFIG a readable TOML file.") from error
    ner = raw.get("ner", {})
    try:
        labels = {Label(key.upper()): str(value) for key, value in ner.get("labels", {}).items()}
        checkpoint = Path(ner["checkpoint"]).expanduser() if ner.get("checkpoint") else None
        threshold = float(ner.get("threshold", NerSettings.threshold))
    except (ValueError, TypeError) as error:
        raise UserError(f"{path}: bad [ner] setting: {error}",
                        f"labels are keyed by {', '.join(Label)}; threshold is a number.") from error
    return Settings(ner=NerSettings(checkpoint, labels, threshold), limits=_limits(raw.get("limits", {}), path),
                    translate=_translate(raw.get("translate", {}), path), keymap=_keymap(raw.get("keymap", {}), path),
                    source=path)


def _translate(raw: dict, path: Path) -> TranslateSettings:
    unknown = set(raw) - set(TranslateSettings.__dataclass_fields__)
    if unknown:
        raise UserError(f"{path}: unknown [translate] setting {', '.join(sorted(unknown))}.",
                        "the settings are primitives (a list of TOML files) and repairs (0 to 10).")
    primitives = raw.get("primitives", [])
    if not isinstance(primitives, list) or not all(isinstance(item, str) and item.strip() for item in primitives):
        raise UserError(f"{path}: [translate] primitives = {primitives!r} is not a list of files.",
                        'write e.g. primitives = ["~/robot/primitives.toml"].')
    repairs = raw.get("repairs", TranslateSettings.repairs)
    if isinstance(repairs, bool) or not isinstance(repairs, int) or not 0 <= repairs <= 10:
        raise UserError(f"{path}: [translate] repairs = {repairs!r} is not a whole number from 0 to 10.",
                        f"the default is {TranslateSettings.repairs}.")
    ground = raw.get("ground", TranslateSettings.ground)
    if not isinstance(ground, bool):
        raise UserError(f"{path}: [translate] ground = {ground!r} is not true or false.",
                        "true checks and completes every plan in the world model (the default).")
    return TranslateSettings(tuple(Path(item).expanduser() for item in primitives), repairs, ground)


def _keymap(raw: dict, path: Path) -> dict[str, str]:
    if not isinstance(raw, dict):
        raise UserError(f"{path}: keymap is not a table.", 'write [keymap] then lines like "translate.run" = "f5".')
    for binding, keys in raw.items():
        if not isinstance(keys, str) or not keys.strip():
            raise UserError(f"{path}: [keymap] {binding} = {keys!r} is not a key.",
                            'give keys as a string, e.g. "ctrl+r" or "f5,ctrl+r".')
    return dict(raw)


def _limits(raw: dict, path: Path) -> Limits:
    unknown = set(raw) - set(Limits.__dataclass_fields__)
    if unknown:
        raise UserError(f"{path}: unknown [limits] setting {', '.join(sorted(unknown))}.",
                        f"the limits are {', '.join(Limits.__dataclass_fields__)}.")
    values = {}
    for name, default in vars(Limits()).items():
        value = raw.get(name, default)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or value <= 0:
            raise UserError(f"{path}: [limits] {name} = {value!r} is not a positive number.",
                            f"the default is {default}.")
        values[name] = type(default)(value)
    return Limits(**values)
