"""Strict span evaluation: a prediction counts only with the exact label, start and end."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from typing import Iterable, Sequence

from cook2ltl.domain.recipe import Label, Span


@dataclass(frozen=True)
class Score:
    true_positives: int
    predicted: int
    gold: int

    @property
    def precision(self) -> float:
        return self.true_positives / self.predicted if self.predicted else 0.0

    @property
    def recall(self) -> float:
        return self.true_positives / self.gold if self.gold else 0.0

    @property
    def f1(self) -> float:
        p, r = self.precision, self.recall
        return 2 * p * r / (p + r) if p + r else 0.0


@dataclass(frozen=True)
class Report:
    overall: Score
    per_label: dict[Label, Score]
    sentences: int


def strict_f1(gold: Sequence[Iterable[Span]], predicted: Sequence[Iterable[Span]]) -> Report:
    """Micro-averaged over sentences, overall and per label."""
    hits, guesses, truths = Counter(), Counter(), Counter()
    for gold_spans, predicted_spans in zip(gold, predicted, strict=True):
        gold_keys = {(s.label, s.start, s.end) for s in gold_spans}
        predicted_keys = {(s.label, s.start, s.end) for s in predicted_spans}
        for key in gold_keys:
            truths[key[0]] += 1
        for key in predicted_keys:
            guesses[key[0]] += 1
            hits[key[0]] += key in gold_keys
    per_label = {label: Score(hits[label], guesses[label], truths[label]) for label in Label}
    overall = Score(sum(hits.values()), sum(guesses.values()), sum(truths.values()))
    return Report(overall, per_label, len(gold))
