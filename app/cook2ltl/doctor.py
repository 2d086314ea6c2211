"""Check the whole stack offline: imports, model files and hashes, and a one-sentence run of each model.

Every check is a plain function returning a `Check`; the CLI only prints them.
"""

from __future__ import annotations

import importlib
import time
from dataclasses import dataclass
from typing import Callable, Iterator

from cook2ltl import offline
from cook2ltl.errors import UserError
from cook2ltl.models.manifest import Source, State, load_manifest, model_path, state_of

FIX_MODELS = "make models"
FIX_INSTALL = "make install"
SMOKE_SENTENCE = "Preheat the oven to 350 F and bake the bread for 20 minutes."
LIBRARIES = ("rich", "typer", "lark", "sqlite_utils", "platformdirs", "torch", "gliner", "spacy", "llama_cpp")


@dataclass(frozen=True)
class Check:
    name: str
    ok: bool
    detail: str
    fix: str = ""


def run_checks() -> Iterator[Check]:
    offline.enforce()
    for library in LIBRARIES:
        yield _check(f"import {library}", lambda: _import(library), FIX_INSTALL)
    manifest = load_manifest()
    for entry in manifest.values():
        state = state_of(entry)
        detail = f"{state.value}: {model_path(entry)}"
        yield Check(f"model {entry.name}", state == State.READY, detail, "" if state == State.READY else FIX_MODELS)
        if state == State.READY:
            yield _check(f"smoke {entry.name}", lambda: _SMOKE[entry.source](entry), FIX_MODELS)


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
        from cook2ltl.parse.spacy_dependencies import SpacyDependencies

        return _timed(lambda: f"{len(SpacyDependencies(entry.module).parse([SMOKE_SENTENCE])[0])} tokens parsed")
    return _timed(lambda: f"{len(list(model_path(entry).rglob('*')))} files load from the package")


def _smoke_span_model(entry) -> str:
    from cook2ltl.parse.gliner_spans import GlinerSpans, checkpoint_label_names

    where = model_path(entry)
    extractor = GlinerSpans(where, checkpoint_label_names(where))
    spans = _timed(lambda: ", ".join(f"{s.label.value}:{s.text}" for s in extractor.extract([SMOKE_SENTENCE])[0]))
    if not spans.split(" (")[0]:
        raise UserError("the span model found nothing in a plain sentence", "retrain: cook2ltl models provision --force")
    return spans


def _smoke_gguf(entry) -> str:
    from llama_cpp import Llama

    def generate() -> str:
        model = Llama(str(model_path(entry)), n_ctx=256, n_threads=2, verbose=False, seed=0)
        output = model("def boil(egg):\n    ", max_tokens=4, temperature=0.0)
        return f"generated {output['usage']['completion_tokens']} tokens"

    return _timed(generate)


_SMOKE = {
    Source.PIP: _smoke_package,
    Source.TRAIN: _smoke_span_model,
    Source.WHEEL: _smoke_gguf,
    Source.SPLIT_WHEELS: _smoke_gguf,
}
