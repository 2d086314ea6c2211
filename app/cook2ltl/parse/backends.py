"""The two model backends of semantic parsing, as small Protocols the core depends on.

Offsets returned by a backend are relative to the sentence it was given; the pipeline makes them absolute.
"""

from __future__ import annotations

from typing import Protocol, Sequence

from cook2ltl.domain.recipe import Span, Token


class SpanExtractor(Protocol):
    """Finds Verb / What? / Where? / How? / Time / Temperature spans (GLiNER in production)."""

    def extract(self, sentences: Sequence[str]) -> list[list[Span]]: ...


class DependencyParser(Protocol):
    """Tokenises and dependency-parses sentences (spaCy in production)."""

    def parse(self, sentences: Sequence[str]) -> list[list[Token]]: ...
