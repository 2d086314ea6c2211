"""The settings file's schema: what each table may hold, with its bounds, checked by pydantic and turned into
settings.py's plain dataclasses (imported by settings_file.py only when a settings file exists)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

from pydantic import Field, StringConstraints

from cook2ltl.domain.recipe import Label
from cook2ltl.domain.settings import Limits, NerSettings, Settings, TranslateSettings
from cook2ltl.paths import shown, user_path
from cook2ltl.toml_models import FileName, PathText, Table, Text, flag, number, validated, whole_number

HINT = "see the README's settings sections; a key left out takes its default."
MAX_PRIMITIVE_SETS = 50
MAX_BINDINGS = 200

LabelName = Annotated[str, StringConstraints(pattern=f"(?i)^({'|'.join(Label)})$"),
                      Field(description=f"one of {', '.join(Label)}")]


class NerTable(Table):
    checkpoint: PathText | None = Field(None, description="the path of a GLiNER checkpoint folder")
    threshold: float = number(NerSettings.threshold, 0.0, 1.0)
    labels: dict[LabelName, Text] = Field({}, description="a table of the checkpoint's names for the categories")


class LimitsTable(Table):
    recipe_bytes: int = whole_number(Limits.recipe_bytes, 1, 10_000_000)
    steps: int = whole_number(Limits.steps, 1, 100_000)
    llm_seconds: float = number(Limits.llm_seconds, 1, 3600)


class TranslateTable(Table):
    primitives: list[FileName] = Field([], max_length=MAX_PRIMITIVE_SETS,
                                       description=f"a list of at most {MAX_PRIMITIVE_SETS} primitive-set files")
    repairs: int = whole_number(TranslateSettings.repairs, 0, 10)
    ground: bool = flag(TranslateSettings.ground)
    reuse: bool = flag(TranslateSettings.reuse)


class SettingsFile(Table):
    ner: NerTable = Field(NerTable(), description="a table")
    limits: LimitsTable = Field(LimitsTable(), description="a table")
    translate: TranslateTable = Field(TranslateTable(), description="a table")
    keymap: dict[Text, Text] = Field({}, max_length=MAX_BINDINGS,
                                     description='a table of binding ids and their keys, e.g. "translate.run" = "f5"')


def settings_from(raw: dict, path: Path) -> Settings:
    file = validated(SettingsFile, raw, path, HINT)
    ner, translate = file.ner, file.translate
    where = f"{shown(path)}: [ner] checkpoint"
    return Settings(
        ner=NerSettings(user_path(ner.checkpoint, where) if ner.checkpoint else None,
                        {Label(name.upper()): text for name, text in ner.labels.items()}, ner.threshold),
        limits=Limits(**file.limits.model_dump()),
        translate=TranslateSettings(tuple(user_path(item, f"{shown(path)}: [translate] primitives")
                                          for item in translate.primitives), translate.repairs, translate.ground,
                                      translate.reuse),
        keymap=dict(file.keymap), source=path)
