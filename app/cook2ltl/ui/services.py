"""The core backends the screens use, built on first use and kept: model loading is slow, so it happens in a
worker the first time a run needs it, never at start-up. Tests build `Services` from fakes."""

from __future__ import annotations

import threading
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from cook2ltl import paths
from cook2ltl.assembly import backends
from cook2ltl.assembly.backends import DEFAULT_MODEL
from cook2ltl.assembly.manifest import load_manifest
from cook2ltl.domain.settings_file import load_settings

if TYPE_CHECKING:
    from cook2ltl.domain.actions import PrimitiveSet
    from cook2ltl.execution.executor import Kitchen
    from cook2ltl.library import Library
    from cook2ltl.parse.backends import DependencyParser, SpanExtractor
    from cook2ltl.reduce.llm import LanguageModel
    from cook2ltl.reduce.validation import PlanValidator


@dataclass
class Services:
    make_spans: Callable[[], SpanExtractor]
    make_dependencies: Callable[[], DependencyParser]
    make_model: Callable[[str], LanguageModel]
    library_path: Path
    start_kitchen: Callable[[str], Kitchen]  # a started Controller (anything with step/reset/last_event/stop)
    make_validator: Callable[[PrimitiveSet], PlanValidator]  # the kitchen check of new reductions
    model_names: tuple[str, ...] = (DEFAULT_MODEL,)
    kitchen_lock: threading.Lock = field(default_factory=threading.Lock)  # one rollout drives the kitchen at a time
    # One run of Algorithm 1 at a time (a translation, or a rollout's planning): the models are not shared
    # across threads.
    pipeline_lock: threading.Lock = field(default_factory=threading.Lock)
    _built: dict[str, Any] = field(default_factory=dict)
    _lock: threading.Lock = field(default_factory=threading.Lock)

    def spans(self) -> SpanExtractor:
        return self._once("spans", self.make_spans)

    def dependencies(self) -> DependencyParser:
        return self._once("dependencies", self.make_dependencies)

    def model(self, name: str, cancel: threading.Event) -> LanguageModel:
        """The named model, stopping at once when the job's `cancel` is set (llama.cpp checks it after every
        token); asking for another model lets the previous one go (one LLM in memory). Hold pipeline_lock."""
        with self._lock:
            if self._built.get("model name") != name:
                self._built.pop("model", None)
                self._built["model"] = self.make_model(name)
                self._built["model name"] = name
            model = self._built["model"]
        model.cancel = cancel
        return model

    def library(self) -> Library:
        from cook2ltl.library import Library  # startup: the app opens before the library (sqlite-utils) loads

        return self._once("library", lambda: Library(self.library_path))

    def validator(self, primitives: PrimitiveSet) -> PlanValidator:
        """One validator per primitive set (each starts its own kitchen at its first plan), shared by the
        translations and the library editor: one plan in its kitchen at a time."""
        return self._once(f"validator {primitives.name}", lambda: OnePlanAtATime(self.make_validator(primitives)))

    def kitchen(self, scene: str) -> Kitchen:
        """The app's one kitchen, started on first use (a rollout resets it to its scene); hold kitchen_lock."""
        return self._once("kitchen", lambda: self.start_kitchen(scene))

    def close(self) -> None:
        with self._lock:
            library, kitchen = self._built.pop("library", None), self._built.pop("kitchen", None)
            validators = [self._built.pop(key) for key in list(self._built) if key.startswith("validator ")]
        if library is not None:
            library.close()
        for validator in validators:
            validator.close()
        if kitchen is not None:
            with self.kitchen_lock:
                kitchen.stop()

    def _once(self, key: str, build: Callable[[], Any]) -> Any:
        with self._lock:
            if key not in self._built:
                self._built[key] = build()
            return self._built[key]


class OnePlanAtATime:
    """A validator several workers may call: its kitchen runs one plan at a time."""

    def __init__(self, validator: PlanValidator) -> None:
        self.validator = validator
        self._lock = threading.Lock()

    def validate(self, action, plan, so_far=None):
        with self._lock:
            return self.validator.validate(action, plan, so_far)

    def close(self) -> None:
        with self._lock:
            self.validator.close()


def production_services() -> Services:
    """GLiNER, spaCy, llama.cpp, the user's library, the embedded kitchen and the kitchen check; nothing is
    loaded yet."""
    def spans():
        return backends.span_extractor(load_settings())

    def dependencies():
        return backends.dependency_parser()

    def model(name: str):
        return backends.load_model(name)

    def kitchen(scene: str):
        # startup: the app opens before the kitchen launcher (~4 ms) loads
        from cook2ltl.execution.launcher import start_kitchen

        return start_kitchen(scene, "embedded")

    def validator(primitives):
        # startup: the app opens before the kitchen check (pydantic, lark) loads
        from cook2ltl.execution.kitchen_check import KitchenValidator

        return KitchenValidator(primitives)

    return Services(spans, dependencies, model, paths.library_file(), kitchen, validator, _language_models())


def _language_models() -> tuple[str, ...]:
    """The GGUF models of the manifest (a TOML read), default first."""
    names = [entry.name for entry in load_manifest().values() if entry.file.endswith(".gguf")]
    return tuple(sorted(names, key=lambda name: name != DEFAULT_MODEL)) or (DEFAULT_MODEL,)
