"""Fakes of the two parsing backends, for unit tests of the core only."""

from __future__ import annotations

import re
from typing import Sequence

from cook2ltl.domain.recipe import Label, Span, Token


class ScriptedSpans:
    """Spans given per sentence as (label, surface) pairs, found in order in the sentence."""

    def __init__(self, script: dict[str, list[tuple[str, str]]]) -> None:
        self.script = script

    def extract(self, sentences: Sequence[str]) -> list[list[Span]]:
        found = []
        for sentence in sentences:
            spans, cursor = [], 0
            for label, surface in self.script.get(sentence, []):
                start = sentence.index(surface, cursor) if surface in sentence[cursor:] else sentence.index(surface)
                spans.append(Span(Label(label), start, start + len(surface), surface))
                cursor = start + len(surface)
            found.append(spans)
        return found


class ScriptedDependencies:
    """Tokens with hand-written (dep, head word) pairs; unlisted words get dep "dep" and head 0."""

    def __init__(self, script: dict[str, dict[str, tuple[str, str]]] | None = None) -> None:
        self.script = script or {}

    def parse(self, sentences: Sequence[str]) -> list[list[Token]]:
        parsed = []
        for sentence in sentences:
            words = [(m.group(), m.start()) for m in re.finditer(r"\w+|[^\w\s]", sentence)]
            index_of = {word: i for i, (word, _) in reversed(list(enumerate(words)))}
            arcs = self.script.get(sentence, {})
            tokens = []
            for word, start in words:
                dep, head = arcs.get(word, (_default_dep(word), words[0][0]))
                tokens.append(Token(word, start, start + len(word), dep, index_of[head]))
            parsed.append(tokens)
        return parsed


def _default_dep(word: str) -> str:
    return {"and": "cc", "or": "cc", "not": "neg", "never": "neg", ",": "punct"}.get(word.lower(), "dep")
