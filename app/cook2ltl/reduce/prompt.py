"""The ProgPrompt-style prompt of the paper's Fig. 4, static part first so llama.cpp keeps it in its KV cache.

    from actions import pick_up, put, open, close, …        ┐ static: the same for every action
    objects = [pot, stovetop, …]                            │ of a primitive set
    def cook(pasta: what):                                  │
        put(water, pot)                                     │
        …                                                   ┘
    from library import boil, chop                          ┐ dynamic: grows with the library,
    objects += [egg]                                        │ and the action's own objects
    def boil(egg: what):                                    ┘ the header the model completes
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import Iterable

from cook2ltl.domain.actions import CONDITION, Action, Call, PrimitiveSet
from cook2ltl.errors import UserError
from cook2ltl.reduce.body import read_body
from cook2ltl.reduce.grammar import INDENT, unusable_verb


@dataclass(frozen=True)
class Prompt:
    static: str
    dynamic: str

    @property
    def text(self) -> str:
        return self.static + self.dynamic

    @property
    def digest(self) -> str:
        return hashlib.sha256(self.text.encode()).hexdigest()


@dataclass(frozen=True)
class Feedback:
    """Why a plan failed in the kitchen, for the model writing it again: the problems as comments under
    the header, then the lines before the first failing one, kept, from which the model goes on; the
    grammar keeps it from calling `avoid` (the failing line's name, `put` for a put before any pick up)
    right there again."""

    problems: tuple[str, ...]
    kept: tuple[Call, ...] = ()
    avoid: tuple[str, ...] = ()


def build_prompt(primitives: PrimitiveSet, library_verbs: Iterable[str], action: Action, comments: bool,
                 feedback: Feedback | None = None) -> Prompt:
    names = {p.name for p in primitives.primitives}
    imported = [verb for verb in dict.fromkeys(library_verbs)
                if verb not in names and verb != action.verb and unusable_verb(verb, ()) is None]
    extra = [name for name in action.objects if name not in primitives.objects]
    lines = []
    if imported:
        lines.append(f"from library import {', '.join(imported)}")
    if extra:
        lines.append(f"objects += [{', '.join(extra)}]")
    dynamic = "\n".join(lines) + "\n\n" if lines else ""
    if feedback is not None:
        return Prompt(static_prefix(primitives, comments), dynamic + header(action) + repair_lines(feedback))
    return Prompt(static_prefix(primitives, comments), dynamic + header(action))


def repair_lines(feedback: Feedback) -> str:
    """What follows the header in a repair prompt:

        def boil(egg: what):
            # this plan failed: line 2 put(egg, pot): the agent holds nothing; the plan must pick up egg first
            open(fridge)
    """
    lines = [f"{INDENT}# this plan failed: {problem}" for problem in feedback.problems]
    return "".join(line + "\n" for line in lines + [INDENT + call.text() for call in feedback.kept])


def static_prefix(primitives: PrimitiveSet, comments: bool) -> str:
    lines = [
        f"from actions import {', '.join(p.name for p in primitives.primitives)}",
        f"objects = [{', '.join(primitives.objects)}]",
        "",
    ]
    for function_header, body in example_functions(primitives):
        lines.append(function_header)
        lines.extend(INDENT + line for line in body if comments or not line.startswith("#"))
        lines.append("")
    return "\n".join(lines) + "\n"  # each function, the last one too, is closed by a blank line


def header(action: Action) -> str:
    """`def bake(cake: what, oven: where, 30_minutes: time):` — the paper's notation, as identifiers."""
    return f"def {action.verb}({', '.join(f'{p.name}: {p.category}' for p in action.parameters)}):\n"


def example_functions(primitives: PrimitiveSet) -> list[tuple[str, list[str]]]:
    """The example functions of the set, each checked to call only its primitives with their arity."""
    functions: list[tuple[str, list[str]]] = []
    for raw in primitives.examples.splitlines():
        line = raw.strip()
        if raw.startswith("def "):
            functions.append((line, []))
        elif line and functions:
            functions[-1][1].append(line)
        elif line:
            raise _bad_examples(primitives, f"{line!r} comes before any `def`")
    arity = {p.name: 2 if p.params == (CONDITION,) else len(p.params) for p in primitives.primitives}
    for function_header, body in functions:
        calls, unread = read_body("\n".join(body))
        if unread:
            raise _bad_examples(primitives, f"in {function_header!r}, {unread[0]!r} is not a call")
        for call in calls:
            if arity.get(call.name) != len(call.args):
                raise _bad_examples(primitives, f"in {function_header!r}, {call.text()} is not one of the primitives")
    if not functions:
        raise _bad_examples(primitives, "there are no example functions")
    return functions


def _bad_examples(primitives: PrimitiveSet, problem: str) -> UserError:
    return UserError(f"The examples of the primitive set {primitives.name!r}: {problem}.",
                     "examples are `def verb(object: what):` lines, each followed by indented primitive calls.")
