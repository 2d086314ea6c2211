"""Check the whole stack offline: what could reach the network, imports, model files and hashes, and a
one-sentence run of each model.

Every check is a plain function returning a `Check`; the CLI only prints them.
"""

from __future__ import annotations

import importlib
import json
import os
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterator

from cook2ltl import offline
from cook2ltl.assembly.backends import SPAN_MODEL
from cook2ltl.assembly.manifest import ModelSource, ModelState, load_manifest, model_path, state_of
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.errors import UserError
from cook2ltl.execution.launcher import THOR_EXECUTABLE_ENV, find_thor_build
from cook2ltl.execution.unavailable import KitchenUnavailable
from cook2ltl.parse.gliner_spans import GlinerSpans, checkpoint_label_names
from cook2ltl.parse.spacy_dependencies import SpacyDependencies

FIX_MODELS = "make models"
FIX_INSTALL = "make install"
SMOKE_SENTENCE = "Preheat the oven to 350 F and bake the bread for 20 minutes."
FIX_LOCAL = "point it at a local file or folder"
PATH_VARIABLES = ("COOK2LTL_MODELS_DIR", "COOK2LTL_MODEL_CACHE", "COOK2LTL_ASSETS", "COOK2LTL_CONFIG", "COOK2LTL_DATA",
                  "COOK2LTL_LIBRARY", "COOK2LTL_THOR_EXECUTABLE", "COOK2LTL_KITCHEN_CACHE")
LIBRARIES = ("rich", "typer", "lark", "sqlite_utils", "platformdirs", "torch", "gliner", "spacy", "llama_cpp")


@dataclass(frozen=True)
class Check:
    name: str
    ok: bool
    detail: str
    fix: str = ""


def run_checks() -> Iterator[Check]:
    offline.enforce()
    yield from network_checks()
    for library in LIBRARIES:
        yield _check(f"import {library}", lambda: _import(library), FIX_INSTALL)
    manifest = load_manifest()
    for entry in manifest.values():
        state = state_of(entry)
        detail = f"{state.value}: {model_path(entry)}"
        ready = state == ModelState.READY
        yield Check(f"model {entry.name}", ready, detail, "" if ready else FIX_MODELS)
        if state == ModelState.READY:
            yield _check(f"smoke {entry.name}", lambda: _SMOKE[entry.source](entry), FIX_MODELS)


def network_checks() -> Iterator[Check]:
    """Everything that could make a library reach for the network, each named with what to change."""
    yield _offline_variables()
    yield from _url_variables()
    try:
        settings = load_settings()
    except UserError as error:
        yield Check("offline: settings", False, error.message, error.hint)
        return
    yield _span_model_offline(settings)
    yield _kitchen_offline()


def _offline_variables() -> Check:
    unset = [name for name, value in offline.as_given.items() if value != "1"]
    if not unset:
        return Check("offline: hub variables", True, f"{', '.join(offline.as_given)} = 1 in your shell too")
    return Check("offline: hub variables", True,
                 f"cook2ltl sets {', '.join(unset)} = 1 for itself; unset in your shell, other tools there "
                 "(pip, huggingface-cli) may reach the hub")


def _url_variables() -> Iterator[Check]:
    for name in PATH_VARIABLES:
        value = os.environ.get(name, "")
        if "://" in value:
            yield Check(f"offline: {name}", False, f"{value} is a URL; cook2ltl reads only local paths", FIX_LOCAL)


def _span_model_offline(settings) -> Check:
    name = "offline: span model"
    configured = settings.ner.checkpoint
    if configured is not None and not configured.is_dir():
        return Check(name, False, f"[ner] checkpoint {configured} is not a local folder: GLiNER would look it up "
                     "on the Hugging Face hub", f"{FIX_LOCAL} in {settings.source}")
    checkpoint = configured or model_path(load_manifest()[SPAN_MODEL])
    try:
        config = json.loads((checkpoint / "gliner_config.json").read_text())
    except (OSError, ValueError):
        return Check(name, True, f"{checkpoint} has no gliner_config.json (the model check below says more)")
    # GLiNER reads the encoder's config and the tokenizer from `model_name` only when the folder lacks them.
    if config.get("encoder_config") and (checkpoint / "tokenizer_config.json").is_file():
        return Check(name, True, f"{checkpoint} holds its encoder config and tokenizer")
    encoder = str(config.get("model_name", ""))
    if encoder and Path(encoder).is_dir():
        return Check(name, True, f"encoder config and tokenizer from the local folder {encoder}")
    if encoder and _in_hub_cache(encoder):
        return Check(name, True, f"encoder {encoder} from the local hub cache (looked up there, never downloaded)")
    return Check(name, False, f"{checkpoint} lacks its encoder config or tokenizer, and {encoder or 'its encoder'} is "
                 "neither a local folder nor in the hub cache: GLiNER would download it",
                 f"retrain with `{FIX_MODELS}`, or give [ner] checkpoint a complete folder")


def _in_hub_cache(repo: str) -> bool:
    hub = Path(os.environ.get("HF_HUB_CACHE") or Path(os.environ.get("HF_HOME", "~/.cache/huggingface")) / "hub")
    return (hub.expanduser() / f"models--{repo.replace('/', '--')}" / "snapshots").is_dir()


def _kitchen_offline() -> Check:
    """ai2thor's Controller downloads a Unity build when it has no local one; cook2ltl always gives it one."""
    try:
        build = find_thor_build()
    except KitchenUnavailable as error:
        if os.environ.get(THOR_EXECUTABLE_ENV):
            return Check("offline: kitchen", False, f"{error.reason}; --backend thor would fail, the embedded "
                         "kitchen is used", f"fix or unset {THOR_EXECUTABLE_ENV}")
        return Check("offline: kitchen", True, "the embedded kitchen (no THOR build is staged, none is downloaded)")
    where = build.executable or f"~/.ai2thor/releases, commit {build.commit_id}"
    return Check("offline: kitchen", True, f"the embedded kitchen, or with --backend thor the local {build.platform} "
                 f"build {where} (never downloaded)")


def _check(name: str, probe: Callable[[], str], fix: str) -> Check:
    try:
        return Check(name, True, probe())
    except UserError as error:
        return Check(name, False, error.message, error.hint or fix)
    except Exception as error:  # a doctor reports every failure instead of stopping at the first
        return Check(name, False, f"{type(error).__name__}: {error}", fix)


def _import(library: str) -> str:
    module = importlib.import_module(library)
    return getattr(module, "__version__", "imported")


def _timed(run: Callable[[], str]) -> str:
    started = time.perf_counter()
    result = run()
    return f"{result} ({time.perf_counter() - started:.1f} s)"


def _smoke_package(entry) -> str:
    if entry.name == "spacy-sm":
        return _timed(lambda: f"{len(SpacyDependencies(entry.module).parse([SMOKE_SENTENCE])[0])} tokens parsed")
    return _timed(lambda: f"{len(list(model_path(entry).rglob('*')))} files load from the package")


def _smoke_span_model(entry) -> str:
    where = model_path(entry)
    extractor = GlinerSpans(where, checkpoint_label_names(where))
    spans = _timed(lambda: ", ".join(f"{s.label.value}:{s.text}" for s in extractor.extract([SMOKE_SENTENCE])[0]))
    if not spans.split(" (")[0]:
        raise UserError("the span model found nothing in a plain sentence", "retrain: cook2ltl models provision --force")
    return spans


def _smoke_gguf(entry) -> str:
    from llama_cpp import Llama  # heavy, optional: llama.cpp loads only for this smoke run

    def generate() -> str:
        model = Llama(str(model_path(entry)), n_ctx=256, n_threads=2, verbose=False, seed=0)
        output = model("def boil(egg):\n    ", max_tokens=4, temperature=0.0)
        return f"generated {output['usage']['completion_tokens']} tokens"

    return _timed(generate)


_SMOKE = {
    ModelSource.PIP: _smoke_package,
    ModelSource.TRAIN: _smoke_span_model,
    ModelSource.WHEEL: _smoke_gguf,
    ModelSource.SPLIT_WHEELS: _smoke_gguf,
}
