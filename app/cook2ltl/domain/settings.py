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
    reuse = true                               # library entries reused across verbs of one table row and signatures
    [keymap]                                   # the app's keys: binding id = keys (a wrong id is named)
    "translate.run" = "ctrl+enter"
    "library.approve" = "y,a"

The file is read by settings_file.py; its schema and bounds are in settings_schema.py. Any other key is
refused, as is a value of the wrong type (0.5 steps, true repairs) or out of bounds.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from cook2ltl.domain.recipe import Label


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
    reuse: bool = True  # reuse a library entry across verbs the verb-effect table reads as one, and signatures


@dataclass(frozen=True)
class Settings:
    ner: NerSettings = NerSettings()
    limits: Limits = Limits()
    translate: TranslateSettings = TranslateSettings()
    keymap: dict[str, str] = field(default_factory=dict)  # binding id -> keys; the app checks the ids
    source: Path | None = None
