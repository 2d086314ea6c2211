"""The parsing backends, loaded once per process and shared by every benchmark of a `cook2ltl bench all`."""

from __future__ import annotations

import time
from dataclasses import dataclass
from functools import cache

from cook2ltl.assembly.backends import dependency_parser, span_extractor
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.parse.backends import DependencyParser, SpanExtractor


@dataclass(frozen=True)
class Parsers:
    spans: SpanExtractor
    dependencies: DependencyParser
    load_seconds: float  # both loaded and run once, when first asked for


@cache
def parsers() -> Parsers:
    started = time.perf_counter()
    spans, dependencies = span_extractor(load_settings()), dependency_parser()
    spans.extract(["Warm up the oven."])
    dependencies.parse(["Warm up the oven."])
    return Parsers(spans, dependencies, time.perf_counter() - started)
