"""Score any SpanExtractor on the held-out recipes, strictly."""

from __future__ import annotations

from pathlib import Path

from cook2ltl.parse.backends import SpanExtractor
from cook2ltl.parse.training.brat import read_corpus
from cook2ltl.parse.training.evaluate import Report, strict_f1
from cook2ltl.parse.training.examples import is_validation, sentence_examples


def validate(extractor: SpanExtractor, data_dir: Path) -> Report:
    held_out = sentence_examples(r for r in read_corpus(data_dir) if is_validation(r.name))
    predicted = extractor.extract([example.text for example in held_out])
    return strict_f1([example.spans for example in held_out], predicted)
