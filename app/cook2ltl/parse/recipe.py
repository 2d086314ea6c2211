"""A whole recipe: sentences → spans and dependencies (batched) → frames → resolved objects.

The text is checked first: hidden characters become spaces, and an empty recipe, or one beyond the
size and step limits of the settings, is a UserError before any model runs.
"""

from __future__ import annotations

from dataclasses import replace

from cook2ltl.domain.recipe import ParsedRecipe, Sentence, Span, Step, Token
from cook2ltl.domain.settings import Limits
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.errors import UserError
from cook2ltl.parse.anaphora import resolve_objects
from cook2ltl.parse.backends import DependencyParser, SpanExtractor
from cook2ltl.parse.frames import build_frames
from cook2ltl.preprocess import split_sentences, visible_text

CONNECTIVES = {"then", "and", "or", "next", "afterwards", "finally"}


def parse_recipe(text: str, spans: SpanExtractor, dependencies: DependencyParser,
                 limits: Limits | None = None) -> ParsedRecipe:
    """`limits` default to the user's settings."""
    text = visible_text(text)
    sentences = recipe_steps(text, limits or load_settings().limits)
    texts = [sentence.text for sentence in sentences]
    found = spans.extract(texts)
    parsed = dependencies.parse(texts)

    steps = []
    for index, (sentence, sentence_spans, tokens) in enumerate(zip(sentences, found, parsed)):
        named = (_shift_span(s, sentence.start) for s in sentence_spans if _names_something(s))
        absolute = tuple(sorted(named, key=lambda s: s.start))
        frames, links = build_frames(absolute, [_shift_token(t, sentence.start) for t in tokens])
        steps.append(Step(index=index, sentence=sentence, spans=absolute, frames=frames, links=links))
    return ParsedRecipe(text=text, steps=_with_resolved_objects(steps))


def recipe_steps(text: str, limits: Limits) -> list[Sentence]:
    size = len(text.encode("utf-8"))
    if size > limits.recipe_bytes:
        raise UserError(f"The recipe is {size:,} bytes; the limit is {limits.recipe_bytes:,}.",
                        "split it into smaller recipes, or raise [limits] recipe_bytes in the settings file.")
    sentences = split_sentences(text)
    if not sentences:
        raise UserError("The recipe is empty: it has no step with a letter or a digit.",
                        "write its instructions, one sentence or line per step.")
    if len(sentences) > limits.steps:
        raise UserError(f"The recipe has {len(sentences):,} steps; the limit is {limits.steps:,}.",
                        "split it into smaller recipes, or raise [limits] steps in the settings file.")
    return sentences


def _names_something(span: Span) -> bool:
    """A span of marks or punctuation alone (a stray accent, an emoji) is no verb or argument, nor one of
    words that only join steps ("then")."""
    words = span.text.lower().replace(",", " ").split()
    return any(ch.isalnum() for ch in span.text) and not (words and set(words) <= CONNECTIVES)


def _with_resolved_objects(steps: list[Step]) -> tuple[Step, ...]:
    resolved = iter(resolve_objects(frame for step in steps for frame in step.frames))
    return tuple(replace(step, frames=tuple(next(resolved) for _ in step.frames)) for step in steps)


def _shift_span(span: Span, offset: int) -> Span:
    return replace(span, start=span.start + offset, end=span.end + offset)


def _shift_token(token: Token, offset: int) -> Token:
    return replace(token, start=token.start + offset, end=token.end + offset)
