"""Zero anaphora: an action with no What? takes the most recent object in context.

The paper filled these by hand ("Blend until slushy" → "Blend the mix until slushy"); here the object is the
latest What? of an earlier action, marked `inferred` and pointing at the mention it came from. A pronoun
("rinse it") is resolved the same way: a robot cannot pick up "it".
"""

from __future__ import annotations

from dataclasses import replace
from typing import Iterable, Iterator

from cook2ltl.domain.recipe import Argument, Connective, Frame

PRONOUNS = {"it", "them", "this", "these", "that", "those", "they", "everything", "all"}


def resolve_objects(frames: Iterable[Frame]) -> Iterator[Frame]:
    """Frames in recipe order, each missing What? filled from the context before it."""
    context: tuple[Argument, ...] = ()
    joined = Connective.AND
    for frame in frames:
        if frame.what and not _only_pronouns(frame.what):
            context, joined = frame.what, frame.objects_joined_by
        elif context:
            inferred = tuple(Argument(argument.span, inferred=True) for argument in context)
            frame = replace(frame, what=inferred, objects_joined_by=joined)
        yield frame


def _only_pronouns(arguments: tuple[Argument, ...]) -> bool:
    return all(argument.span.text.lower() in PRONOUNS for argument in arguments)
