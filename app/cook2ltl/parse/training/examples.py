"""Annotated recipes → per-sentence training examples in GLiNER's word-level format."""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterable, Mapping

from cook2ltl.domain.recipe import Label, Span
from cook2ltl.parse.training.brat import AnnotatedRecipe
from cook2ltl.preprocess import split_sentences

# GLiNER's own word splitter, so word indices agree with what the model sees at inference.
WORD = re.compile(r"\w+(?:[-_]\w+)*|\S")
# Recipes held out for validation: every fifth one, a fixed and documented choice (14 of 70).
VALIDATION_EVERY = 5


@dataclass(frozen=True)
class SentenceExample:
    recipe: str
    text: str
    spans: tuple[Span, ...]  # offsets relative to `text`


def is_validation(recipe_name: str) -> bool:
    number = int(re.sub(r"\D", "", recipe_name) or 0)
    return number % VALIDATION_EVERY == VALIDATION_EVERY - 1


def sentence_examples(recipes: Iterable[AnnotatedRecipe]) -> list[SentenceExample]:
    """Each sentence with the gold spans that lie inside it (spans crossing a boundary are dropped)."""
    examples = []
    for recipe in recipes:
        for sentence in split_sentences(recipe.text):
            inside = tuple(
                Span(s.label, s.start - sentence.start, s.end - sentence.start, s.text)
                for s in recipe.spans
                if sentence.start <= s.start and s.end <= sentence.end
            )
            examples.append(SentenceExample(recipe.name, sentence.text, inside))
    return examples


def words(text: str) -> list[tuple[int, int]]:
    return [(m.start(), m.end()) for m in WORD.finditer(text)]


def to_gliner(example: SentenceExample, label_names: Mapping[Label, str]) -> dict | None:
    """{"tokenized_text", "ner"} with inclusive word indices; spans not on word boundaries are left out."""
    bounds = words(example.text)
    if not bounds:
        return None
    starts = {start: i for i, (start, _) in enumerate(bounds)}
    ends = {end: i for i, (_, end) in enumerate(bounds)}
    ner = [
        [starts[s.start], ends[s.end], label_names[s.label]]
        for s in example.spans
        if s.start in starts and s.end in ends
    ]
    return {"tokenized_text": [example.text[a:b] for a, b in bounds], "ner": ner}
