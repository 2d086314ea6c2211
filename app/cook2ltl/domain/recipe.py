"""Frozen dataclasses every pipeline stage shares: spans, sentences, frames, steps."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import StrEnum


class Label(StrEnum):
    """The paper's six salient categories (Sec. IV-C)."""

    VERB = "VERB"
    WHAT = "WHAT"
    WHERE = "WHERE"
    HOW = "HOW"
    TIME = "TIME"
    TEMP = "TEMP"


ARGUMENT_LABELS = (Label.WHAT, Label.WHERE, Label.HOW, Label.TIME, Label.TEMP)


class Connective(StrEnum):
    AND = "and"
    OR = "or"


@dataclass(frozen=True)
class Span:
    """A labelled piece of the input; start/end are character offsets into the text as given."""

    label: Label
    start: int
    end: int
    text: str
    score: float = 1.0


@dataclass(frozen=True)
class Sentence:
    """One instruction step r_i, with its offsets into the whole recipe."""

    text: str
    start: int
    end: int


@dataclass(frozen=True)
class Token:
    """A token of a dependency parse, offsets absolute like every span."""

    text: str
    start: int
    end: int
    dep: str
    head: int  # index of the head token within the sentence; the root points to itself


@dataclass(frozen=True)
class Argument:
    """A filled parameter of a frame; `inferred` marks an object resolved by zero anaphora."""

    span: Span
    inferred: bool = False


@dataclass(frozen=True)
class Frame:
    """The function representation a = Verb(What, Where, How, Time, Temperature)."""

    verb: Span
    what: tuple[Argument, ...] = ()
    where: tuple[Argument, ...] = ()
    how: tuple[Argument, ...] = ()
    time: tuple[Argument, ...] = ()
    temperature: tuple[Argument, ...] = ()
    negated: bool = False
    objects_joined_by: Connective = Connective.AND
    particle: str = ""  # of a phrasal verb outside the verb's span: "turn the oven *on*"

    @property
    def name(self) -> str:
        return f"{self.verb.text} {self.particle}".lower() if self.particle else self.verb.text.lower()

    def arguments(self, label: Label) -> tuple[Argument, ...]:
        return getattr(self, _FIELD_OF[label])

    def signature(self) -> str:
        """`verb(what, where, …)` in the paper's notation."""
        parts = []
        for label in ARGUMENT_LABELS:
            for argument in self.arguments(label):
                parts.append(argument.span.text)
        call = f"{self.name}({', '.join(parts)})"
        return f"not {call}" if self.negated else call


_FIELD_OF = {
    Label.WHAT: "what",
    Label.WHERE: "where",
    Label.HOW: "how",
    Label.TIME: "time",
    Label.TEMP: "temperature",
}


def field_of(label: Label) -> str:
    return _FIELD_OF[label]


@dataclass(frozen=True)
class Step:
    """A parsed instruction step: its spans, frames and how consecutive frames are joined.

    `links[i]` joins frames[i] and frames[i + 1]: AND is "then" (sequence), OR an alternative.
    """

    index: int
    sentence: Sentence
    spans: tuple[Span, ...]
    frames: tuple[Frame, ...]
    links: tuple[Connective, ...] = field(default=())


@dataclass(frozen=True)
class ParsedRecipe:
    text: str
    steps: tuple[Step, ...]
