"""A whole recipe: sentences → spans and dependencies (batched) → frames → resolved objects."""

from __future__ import annotations

from dataclasses import replace

from cook2ltl.domain import ParsedRecipe, Span, Step, Token
from cook2ltl.parse.anaphora import resolve_objects
from cook2ltl.parse.backends import DependencyParser, SpanExtractor
from cook2ltl.parse.frames import build_frames
from cook2ltl.preprocess import split_sentences


def parse_recipe(text: str, spans: SpanExtractor, dependencies: DependencyParser) -> ParsedRecipe:
    sentences = split_sentences(text)
    texts = [sentence.text for sentence in sentences]
    found = spans.extract(texts) if texts else []
    parsed = dependencies.parse(texts) if texts else []

    steps = []
    for index, (sentence, sentence_spans, tokens) in enumerate(zip(sentences, found, parsed)):
        absolute = tuple(sorted((_shift_span(s, sentence.start) for s in sentence_spans), key=lambda s: s.start))
        frames, links = build_frames(absolute, [_shift_token(t, sentence.start) for t in tokens])
        steps.append(Step(index=index, sentence=sentence, spans=absolute, frames=frames, links=links))
    return ParsedRecipe(text=text, steps=_with_resolved_objects(steps))


def _with_resolved_objects(steps: list[Step]) -> tuple[Step, ...]:
    resolved = iter(resolve_objects(frame for step in steps for frame in step.frames))
    return tuple(replace(step, frames=tuple(next(resolved) for _ in step.frames)) for step in steps)


def _shift_span(span: Span, offset: int) -> Span:
    return replace(span, start=span.start + offset, end=span.end + offset)


def _shift_token(token: Token, offset: int) -> Token:
    return replace(token, start=token.start + offset, end=token.end + offset)
