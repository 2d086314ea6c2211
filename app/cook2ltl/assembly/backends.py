"""The production backends, built from settings and the model manifest; nothing heavy is imported here."""

from __future__ import annotations

from pathlib import Path

from cook2ltl import paths
from cook2ltl.assembly.manifest import ModelState, load_manifest, model_path, state_of
from cook2ltl.domain.recipe import Label
from cook2ltl.domain.settings import Settings
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.errors import UserError
from cook2ltl.parse.gliner_spans import GlinerSpans, checkpoint_label_names
from cook2ltl.parse.spacy_dependencies import SpacyDependencies
from cook2ltl.reduce.llm import LlamaModel

SPAN_MODEL = "gliner-cook2ltl"
DEPENDENCY_MODEL = "spacy-sm"
DEFAULT_MODEL = "qwen2.5-coder-1.5b"  # chosen by measurement: see the README's "Action reduction"


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
    if state_of(entry, verify_hash=False) != ModelState.READY:
        raise _not_provisioned(DEPENDENCY_MODEL)
    return SpacyDependencies(entry.module)


def load_model(name: str = DEFAULT_MODEL, lanes: int = 1) -> LlamaModel:
    """A GGUF model of the manifest by name; it is read from disk at its first completion. With `lanes` > 1,
    that many threads may use it at once, their completions decoded in one batch."""
    manifest = load_manifest()
    choices = [entry.name for entry in manifest.values() if entry.file.endswith(".gguf")]
    entry = manifest.get(name)
    if entry is None or name not in choices:
        raise UserError(f"No language model {name!r} in the model manifest.", f"choose one of: {', '.join(choices)}.")
    if state_of(entry, verify_hash=False) != ModelState.READY:
        raise UserError(f"The model {name!r} is not provisioned.", "run `make models` (or `cook2ltl models provision`).")
    time_limit = load_settings().limits.llm_seconds
    if lanes > 1:
        from cook2ltl.reduce.batched import BatchedLlamaModel  # heavy: numpy (~150 ms), only for batched decoding

        return BatchedLlamaModel(name, model_path(entry), lanes, time_limit=time_limit)
    return LlamaModel(name, model_path(entry), state_dir=paths.model_cache_dir() / "prompt-states",
                      time_limit=time_limit)


def _provisioned(name: str) -> Path:
    entry = load_manifest()[name]
    if state_of(entry, verify_hash=False) != ModelState.READY:
        raise _not_provisioned(name)
    return model_path(entry)


def _not_provisioned(name: str) -> UserError:
    return UserError(f"The model {name!r} is not provisioned.", "run `make models` (it fetches or trains what is missing).")
