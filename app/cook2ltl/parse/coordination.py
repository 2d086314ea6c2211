"""and / or / not from a dependency parse: between actions, between objects, and negation."""

from __future__ import annotations

import re
from dataclasses import replace
from typing import Sequence

from cook2ltl.domain.recipe import Connective, Span, Token

_VERB_SEPARATOR = re.compile(r"\s*,?\s*\b(?:and/or|and then|and|or|then)\b\s*|\s*,\s*|\s*/\s*", re.IGNORECASE)
_OR = re.compile(r"\bor\b", re.IGNORECASE)
# A span model may take the negation into the verb ("Do not boil"); the verb is what follows it.
_LEADING_NEGATION = re.compile(r"^(?:do\s+not|don'?t|do\s+n't|never|not)\s+", re.IGNORECASE)
NEGATIONS = {"not", "n't", "never"}


def split_verb(span: Span) -> list[tuple[Span, Connective]]:
    """"Butter or oil" is two actions: each part with the connective that joins it to the next one."""
    negation = _LEADING_NEGATION.match(span.text)
    if negation and negation.end() < len(span.text):
        span = _piece(span, negation.end(), len(span.text))
    parts: list[tuple[Span, Connective]] = []
    cursor = 0
    for match in _VERB_SEPARATOR.finditer(span.text):
        if match.start() > cursor:
            joined = Connective.OR if _OR.search(match.group(0)) else Connective.AND
            parts.append((_piece(span, cursor, match.start()), joined))
        cursor = match.end()
    if cursor < len(span.text):
        parts.append((_piece(span, cursor, len(span.text)), Connective.AND))
    return parts or [(span, Connective.AND)]


def _piece(span: Span, start: int, end: int) -> Span:
    return replace(span, start=span.start + start, end=span.start + end, text=span.text[start:end])


def connective_between(left_end: int, right_start: int, tokens: Sequence[Token], arguments: Sequence[Span]) -> Connective:
    """OR when a coordinating "or" that belongs to no argument stands between two actions."""
    between = _free_tokens(left_end, right_start, tokens, arguments)
    return Connective.OR if any(t.dep == "cc" and t.text.lower() == "or" for t in between) else Connective.AND


def is_negated(segment_start: int, verb: Span, tokens: Sequence[Token], arguments: Sequence[Span]) -> bool:
    """A negation before the verb in its own segment ("Do not overmix", "never stir"), not inside an
    argument of the previous action ("stir until no longer lumpy")."""
    before = _free_tokens(segment_start, verb.end, tokens, arguments)
    return any(t.dep == "neg" or t.text.lower() in NEGATIONS for t in before)


def _free_tokens(start: int, end: int, tokens: Sequence[Token], arguments: Sequence[Span]) -> list[Token]:
    """Tokens within [start, end) that belong to no argument span."""
    return [t for t in tokens if start <= t.start and t.end <= end and not _inside_any(t, arguments)]


def split_objects(span: Span, tokens: Sequence[Token]) -> tuple[list[Span], Connective]:
    """Coordinated objects in one span ("salt or pepper") become several, with how they are joined."""
    inside = [t for t in tokens if span.start <= t.start and t.end <= span.end]
    separators = [t for t in inside if t.dep == "cc" or (t.dep == "punct" and t.text == ",")]
    conjuncts = [t for t in inside if t.dep == "conj" and _head(t, tokens) in inside]
    if not conjuncts or not separators:
        return [span], Connective.AND
    joined = Connective.OR if any(t.text.lower() == "or" for t in separators) else Connective.AND
    pieces: list[Span] = []
    cursor = span.start
    for separator in separators:
        pieces.append(_trimmed(span, cursor, separator.start))
        cursor = separator.end
    pieces.append(_trimmed(span, cursor, span.end))
    pieces = [piece for piece in pieces if piece.text]
    return (pieces, joined) if len(pieces) > 1 else ([span], Connective.AND)


def _trimmed(span: Span, start: int, end: int) -> Span:
    text = span.text[start - span.start:end - span.start]
    lead = len(text) - len(text.lstrip())
    text = text.strip()
    return replace(span, start=start + lead, end=start + lead + len(text), text=text)


def _head(token: Token, tokens: Sequence[Token]) -> Token:
    return tokens[token.head] if 0 <= token.head < len(tokens) else token


def _inside_any(token: Token, spans: Sequence[Span]) -> bool:
    return any(span.start <= token.start and token.end <= span.end for span in spans)
