"""What a plan line may say, as data; rendered as a GBNF grammar for llama.cpp and checked line by line.

The vocabulary is built per action from the primitive set, the library's verbs, the environment's objects
and states, and the action's own arguments, so a constrained model can only write admissible lines. Every
word goes into the grammar through `gbnf_literal`, so no text (an imported library's verb, say) can be
read by llama.cpp as grammar syntax; a library verb that is not a name a plan line can call is left out.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterable

from cook2ltl.domain.actions import CONDITION, TIMER, Action, Call, PrimitiveSet

OBJECT, VALUE = "object", "value"  # slot kinds besides CONDITION
DURATION_UNITS = ("seconds", "minutes", "hours")
_DURATION = re.compile(r"[1-9][0-9]{0,2}_(seconds|minutes|hours)\Z")
_NAME = re.compile(r"[a-z][a-z0-9_]*\Z")  # a name a plan line can call (what reduce.body reads back)
_ARGUMENT = re.compile(r"[a-z0-9][a-z0-9_]*\Z")  # and a word it can pass
# GBNF string escapes for what may not appear as itself between quotes.
_GBNF_ESCAPES = {"\\": "\\\\", '"': '\\"', "\n": "\\n", "\r": "\\r", "\t": "\\t"}
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
        if verb not in taken and unusable_verb(verb, signature) is None:
            shapes.append(Shape(verb, tuple(VALUE if c in ("time", "temperature") else OBJECT for c in signature)))
    # "30 minutes" is a duration a timer waits for; "350 degrees" or "until golden" a state to reach.
    durations = _arguments(p.value for p in action.parameters if p.category == "time" and p.value[:1].isdigit())
    names = {shape.name for shape in shapes}  # a state named like an action would read as that action
    return Vocabulary(
        shapes=tuple(dict.fromkeys(shapes)),
        objects=_arguments((*primitives.objects, *action.objects)),
        states=_arguments(v for v in (*primitives.states, *action.values) if v not in durations and v not in names),
        durations=durations,
    )


def _arguments(words: Iterable[str]) -> tuple[str, ...]:
    """The words a plan line can pass (what reduce.body reads back), once each, in order."""
    return tuple(dict.fromkeys(word for word in words if _ARGUMENT.match(word)))


def unusable_verb(verb: str, signature: tuple[str, ...]) -> str | None:
    """Why a library verb cannot be offered to the model (its name or a parameter is no identifier), or None."""
    if not _NAME.match(verb):
        return f"the library verb {verb!r} is not a lower-case identifier; it is not offered to the model"
    if not all(isinstance(category, str) and _NAME.match(category) for category in signature):
        return f"the library verb {verb!r} has a parameter that is not an identifier; it is not offered to the model"
    return None


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
    durations = [*(gbnf_literal(d) for d in vocab.durations), '[1-9] [0-9]{0,2} "_" (' + _choice(DURATION_UNITS) + ")"]
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
        return gbnf_literal(f"{shape.name}()")
    slots = ' ", " '.join(shape.slots)
    return f"{gbnf_literal(shape.name + '(')} {slots} {gbnf_literal(')')}"


def _choice(words: Iterable[str]) -> str:
    return " | ".join(gbnf_literal(word) for word in words)


def gbnf_literal(text: str) -> str:
    """`text` as a GBNF string literal that matches exactly it: quotes, backslashes and line breaks escaped,
    every other control or invisible character as a \\x or \\u escape (llama.cpp reads all of these)."""
    return '"' + "".join(_gbnf_char(c) for c in text) + '"'


def _gbnf_char(char: str) -> str:
    if char in _GBNF_ESCAPES:
        return _GBNF_ESCAPES[char]
    code = ord(char)
    if char.isprintable():
        return char
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}" if code < 0x10000 else f"\\U{code:08x}"
