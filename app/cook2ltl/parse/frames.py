"""Spans → frames: one `Verb(What, Where, How, Time, Temperature)` per detected action.

Arguments belong to the action whose verb precedes them in the sentence (recipes are imperative: the verb
comes first); those before the first verb ("In a bowl, mix …") belong to it. An action with no arguments of its
own that is coordinated with the next one ("Bake or grill the chicken") shares that action's arguments.
"""

from __future__ import annotations

from typing import Sequence

from cook2ltl.domain.recipe import ARGUMENT_LABELS, Argument, Connective, Frame, Label, Span, Token, field_of
from cook2ltl.parse.coordination import connective_between, is_negated, split_objects, split_verb
from cook2ltl.parse.verb_syntax import missed_objects, particle


def build_frames(spans: Sequence[Span], tokens: Sequence[Token]) -> tuple[tuple[Frame, ...], tuple[Connective, ...]]:
    """Frames of one sentence and the connectives joining consecutive frames."""
    verbs, verb_links = _verbs(spans)
    if not verbs:
        return (), ()
    arguments = [span for span in spans if span.label != Label.VERB]
    arguments += missed_objects(verbs, tokens, spans)
    owned: list[list[Span]] = [[] for _ in verbs]
    for argument in arguments:
        owned[_owner(argument, verbs)].append(argument)
    _share_with_coordinated(owned)

    frames = []
    for index, verb in enumerate(verbs):
        segment_start = verbs[index - 1].end if index else 0
        frames.append(_frame(verb, owned[index], tokens, is_negated(segment_start, verb, tokens, arguments)))
    links = tuple(
        Connective.OR if joined == Connective.OR else connective_between(left.end, right.start, tokens, arguments)
        for joined, left, right in zip(verb_links, verbs, verbs[1:])
    )
    return tuple(frames), links


def _verbs(spans: Sequence[Span]) -> tuple[list[Span], list[Connective]]:
    verbs: list[Span] = []
    links: list[Connective] = []
    for span in sorted((s for s in spans if s.label == Label.VERB), key=lambda s: s.start):
        for piece, joined in split_verb(span):
            verbs.append(piece)
            links.append(joined)
    return verbs, links[:-1] if links else []


def _owner(argument: Span, verbs: Sequence[Span]) -> int:
    preceding = [i for i, verb in enumerate(verbs) if verb.start <= argument.start]
    return preceding[-1] if preceding else 0


def _share_with_coordinated(owned: list[list[Span]]) -> None:
    """An action with nothing of its own shares the next one's arguments; walking backwards lets
    "chop, peel or grate the carrot" give all three the carrot."""
    for index in range(len(owned) - 2, -1, -1):
        if not owned[index]:
            owned[index] = list(owned[index + 1])


def _frame(verb: Span, arguments: Sequence[Span], tokens: Sequence[Token], negated: bool) -> Frame:
    verb_particle, arguments = particle(verb, tokens, arguments)
    filled: dict[str, list[Argument]] = {field_of(label): [] for label in ARGUMENT_LABELS}
    joined = Connective.AND
    for span in sorted(arguments, key=lambda s: s.start):
        if span.label == Label.WHAT:
            pieces, how = split_objects(span, tokens)
            joined = Connective.OR if how == Connective.OR else joined
            filled["what"].extend(Argument(piece) for piece in pieces)
        else:
            filled[field_of(span.label)].append(Argument(span))
    return Frame(verb=verb, negated=negated, objects_joined_by=joined, particle=verb_particle,
                 **{k: tuple(v) for k, v in filled.items()})

