"""The production backends, built from settings and the model manifest; nothing heavy is imported here."""

from __future__ import annotations

from pathlib import Path

from cook2ltl.domain import Label
from cook2ltl.errors import UserError
from cook2ltl.models.manifest import State, load_manifest, model_path, state_of
from cook2ltl.parse.gliner_spans import GlinerSpans, checkpoint_label_names
from cook2ltl.parse.spacy_dependencies import SpacyDependencies
from cook2ltl.settings import Settings

SPAN_MODEL = "gliner-cook2ltl"
DEPENDENCY_MODEL = "spacy-sm"


def span_extractor(settings: Settings) -> GlinerSpans:
    checkpoint = settings.ner.checkpoint or _provisioned(SPAN_MODEL)
    if not checkpoint.is_dir():
        raise UserError(f"NER checkpoint {checkpoint} is not a folder.", "set [ner] checkpoint to a GLiNER folder.")
    names = {**(checkpoint_label_names(checkpoint) or {}), **settings.ner.labels}
    missing = [label.value for label in Label if label not in names]
    if missing:
        raise UserError(f"No label names for {', '.join(missing)} for the checkpoint {checkpoint}.",
                        "give them under [ner.labels] in the settings file, e.g. VERB = \"action\".")
    return GlinerSpans(checkpoint, names, settings.ner.threshold)


def dependency_parser() -> SpacyDependencies:
    entry = load_manifest()[DEPENDENCY_MODEL]
    if state_of(entry, verify_hash=False) != State.READY:
        raise _not_provisioned(DEPENDENCY_MODEL)
    return SpacyDependencies(entry.module)


def _provisioned(name: str) -> Path:
    entry = load_manifest()[name]
    if state_of(entry, verify_hash=False) != State.READY:
        raise _not_provisioned(name)
    return model_path(entry)


def _not_provisioned(name: str) -> UserError:
    return UserError(f"The model {name!r} is not provisioned.", "run `make models` (it fetches or trains what is missing).")
