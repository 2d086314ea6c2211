"""Frames → actions: the verb and arguments as identifiers a prompt, a grammar and an atom can use."""

from __future__ import annotations

import re
from collections.abc import Collection

from cook2ltl.domain.actions import Action, Parameter
from cook2ltl.domain.recipe import ARGUMENT_LABELS, Connective, Frame, Label, field_of

CATEGORY = {Label.WHAT: "what", Label.WHERE: "where", Label.HOW: "how", Label.TIME: "time", Label.TEMP: "temperature"}
# Leading words that do not name the thing: "the penne", "2 eggs", "rest of the mix".
OBJECT_FILLERS = frozenset("a an the some any your its their this that these those each all of rest remaining".split())
# Leading words of a time or temperature that do not name the state or duration reached.
MARKERS = frozenset("until till for about around approximately once when after before over at to on in with is are".split())
# Words after which a time or temperature goes on with another one: "20 minutes or until golden".
CLAUSE_ENDS = frozenset("or and before after then while".split())
# Leading words of a where or how that link it to the action: "in a pot", "with olive oil".
LINKS = frozenset("into in with on onto to over using by from".split())
_WORD = re.compile(r"[a-z0-9]+")
OBJECTS = ("what", "where", "how")


def actions_of(frame: Frame) -> tuple[Action, ...]:
    """One action, or one per object when the objects are alternatives ("add salt or pepper")."""
    parameters = _parameters(frame)
    whats = [p for p in parameters if p.category == "what"]
    if frame.objects_joined_by != Connective.OR or len(whats) < 2:
        return (Action(verb_identifier(frame.name), parameters),)
    others = tuple(p for p in parameters if p.category != "what")
    return tuple(Action(verb_identifier(frame.name), (what, *others)) for what in whats)


def known_objects(action: Action, known: Collection[str]) -> Action:
    """The action with each object the kitchen does not know by its name given its head noun's name where the
    kitchen knows that one (the dirty_plate is the plate): the last word of a name is the thing it names."""
    def known_as(parameter: Parameter) -> Parameter:
        head = parameter.value.rsplit("_", 1)[-1]
        if parameter.category not in OBJECTS or parameter.value in known or head not in known:
            return parameter
        return Parameter(parameter.category, parameter.text, head, head)

    return Action(action.verb, tuple(known_as(p) for p in action.parameters))


def verb_identifier(verb: str) -> str:
    return "_".join(_WORD.findall(verb.lower())) or "do"


def _parameters(frame: Frame) -> tuple[Parameter, ...]:
    parameters = []
    for label in ARGUMENT_LABELS:
        for argument in getattr(frame, field_of(label)):
            parameters.append(parameter(CATEGORY[label], argument.span.text))
    return tuple(parameters)


def parameter(category: str, text: str) -> Parameter:
    words = _WORD.findall(text.lower().replace("'s", ""))
    if category == "what":
        value = _identifier(_strip(words, OBJECT_FILLERS, keep_numbers=False))
        return Parameter(category, text, value, value)
    if category in ("where", "how"):  # "in a saucepan" is the saucepan; a how may be "375 F"
        value = _identifier(_strip(_strip(words, LINKS, True), OBJECT_FILLERS, keep_numbers=category == "how"))
        return Parameter(category, text, value, value)
    value = _strip(words, MARKERS, keep_numbers=True)
    end = next((i for i, word in enumerate(value) if word in CLAUSE_ENDS and i), len(value))
    return Parameter(category, text, _identifier(words), _identifier(value[:end]))


def _strip(words: list[str], fillers: frozenset[str], keep_numbers: bool) -> list[str]:
    start = 0
    while start < len(words) - 1 and (words[start] in fillers or (not keep_numbers and words[start].isdigit())):
        start += 1
    return words[start:]


def _identifier(words: list[str]) -> str:
    return "_".join(words) or "it"
