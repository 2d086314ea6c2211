"""What a plan line may say, as data; rendered as a GBNF grammar for llama.cpp and checked line by line.

The vocabulary is built per action from the primitive set, the library's verbs, the environment's objects
and states, and the action's own arguments, so a constrained model can only write admissible lines.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterable

from cook2ltl.reduce.model import CONDITION, TIMER, Action, Call, PrimitiveSet

OBJECT, VALUE = "object", "value"  # slot kinds besides CONDITION
DURATION_UNITS = ("seconds", "minutes", "hours")
_DURATION = re.compile(r"[1-9][0-9]{0,2}_(seconds|minutes|hours)\Z")
INDENT = "    "
COMMENT_CHARACTERS = 60


@dataclass(frozen=True)
class Shape:
    """A callable name and the kind of each slot."""

    name: str
    slots: tuple[str, ...]


@dataclass(frozen=True)
class Vocabulary:
    shapes: tuple[Shape, ...]
    objects: tuple[str, ...]
    states: tuple[str, ...]
    durations: tuple[str, ...]


def vocabulary(primitives: PrimitiveSet, library_verbs: Iterable[tuple[str, tuple[str, ...]]], action: Action) -> Vocabulary:
    """Primitives, then library verbs (other than the action's own and the primitives' names)."""
    shapes = [Shape(p.name, tuple(CONDITION if k == CONDITION else OBJECT for k in p.params)) for p in primitives.primitives]
    taken = {p.name for p in primitives.primitives} | {action.verb}
    for verb, signature in library_verbs:
        if verb not in taken:
            shapes.append(Shape(verb, tuple(VALUE if c in ("time", "temperature") else OBJECT for c in signature)))
    # "30 minutes" is a duration a timer waits for; "350 degrees" or "until golden" a state to reach.
    durations = tuple(dict.fromkeys(p.value for p in action.parameters if p.category == "time" and p.value[:1].isdigit()))
    names = {shape.name for shape in shapes}  # a state named like an action would read as that action
    return Vocabulary(
        shapes=tuple(dict.fromkeys(shapes)),
        objects=tuple(dict.fromkeys((*primitives.objects, *action.objects))),
        states=tuple(dict.fromkeys(v for v in (*primitives.states, *action.values) if v not in durations and v not in names)),
        durations=durations,
    )


def admits(vocab: Vocabulary, call: Call) -> bool:
    """Whether the grammar would have let the model write this call."""
    for shape in vocab.shapes:
        if shape.name != call.name:
            continue
        if shape.slots == (CONDITION,):
            if len(call.args) == 2 and _condition_ok(vocab, *call.args):
                return True
        elif len(shape.slots) == len(call.args) and all(
            _slot_ok(vocab, kind, arg) for kind, arg in zip(shape.slots, call.args)
        ):
            return True
    return False


def _condition_ok(vocab: Vocabulary, subject: str, state: str) -> bool:
    if subject == TIMER:
        return _is_duration(vocab, state)
    return subject in vocab.objects and state in vocab.states


def _slot_ok(vocab: Vocabulary, kind: str, arg: str) -> bool:
    if kind == OBJECT:
        return arg in vocab.objects
    return arg in vocab.states or _is_duration(vocab, arg)


def _is_duration(vocab: Vocabulary, text: str) -> bool:
    return text in vocab.durations or bool(_DURATION.match(text))


def to_gbnf(vocab: Vocabulary, max_lines: int, comments: bool, avoid: Iterable[str] = ()) -> str:
    """One body: 1 … max_lines indented calls (each after an optional comment), then a blank line.

    `avoid` are names the first line may not call: a repair must not write again, where the plan failed,
    the kind of line that failed there (a greedy model shown its failed plan would write it again)."""
    calls = " | ".join(_shape_rule(shape) for shape in vocab.shapes)
    first = " | ".join(_shape_rule(shape) for shape in vocab.shapes if shape.name not in set(avoid))
    first = first if first != calls else ""
    conditions = (['object " == " state'] if vocab.states else []) + [f'"{TIMER} == " duration']
    durations = [*(_literal(d) for d in vocab.durations), '[1-9] [0-9]{0,2} "_" (' + _choice(DURATION_UNITS) + ")"]
    comment = "comment? " if comments else ""
    rules = [
        f'root ::= first line{{0,{max_lines - 1}}} "\\n"' if first else f'root ::= line{{1,{max_lines}}} "\\n"',
        f'line ::= {comment}"{INDENT}" call "\\n"',
        f"call ::= {calls}",
        f"object ::= {_choice(vocab.objects)}",
        f"duration ::= {' | '.join(durations)}",
        f"condition ::= {' | '.join(conditions)}",
        f"value ::= {'state | ' if vocab.states else ''}duration",
    ]
    if vocab.states:
        rules.append(f"state ::= {_choice(vocab.states)}")
    if comments:
        rules.append(f'comment ::= "{INDENT}# " [a-zA-Z0-9 ,\'-]{{1,{COMMENT_CHARACTERS}}} "\\n"')
    if first:
        rules += [f'first ::= {comment}"{INDENT}" first-call "\\n"', f"first-call ::= {first}"]
    return "\n".join(rules) + "\n"


def _shape_rule(shape: Shape) -> str:
    if not shape.slots:
        return _literal(f"{shape.name}()")
    slots = ' ", " '.join(shape.slots)
    return f'"{shape.name}(" {slots} ")"'


def _choice(words: Iterable[str]) -> str:
    return " | ".join(_literal(word) for word in words)


def _literal(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'
