"""Plan bodies as text: lines of calls, read and written, and made parametric for the library.

A library body names the action's parameters as `$what`, `$what2`, `$where`, `$time` …, so the body
learnt for boil(egg) serves boil(potato), while constants such as `pot` or `microwave` stay as written.
"""

from __future__ import annotations

import re
from collections import Counter

from cook2ltl.domain.actions import Action, Call

_CALL = re.compile(r"(?P<name>[a-z][a-z0-9_]*)\((?P<args>[^()]*)\)\Z")
_CONDITION = re.compile(r"(?P<subject>\$?[a-z0-9_]+)\s*==\s*(?P<state>\$?[a-z0-9_]+)\Z")
_ARG = re.compile(r"\$?[a-z0-9][a-z0-9_]*\Z")


def read_body(text: str) -> tuple[tuple[Call, ...], tuple[str, ...]]:
    """The calls of a body, and the lines that are not calls (comments and blanks are skipped)."""
    calls, unread = [], []
    for raw in text.splitlines():
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        call = read_call(line)
        if call is None:
            unread.append(line)
        else:
            calls.append(call)
    return tuple(calls), tuple(unread)


def read_call(line: str) -> Call | None:
    match = _CALL.match(line.strip())
    if not match:
        return None
    name, inside = match["name"], match["args"].strip()
    if name == "wait":
        condition = _CONDITION.match(inside)
        return Call(name, (condition["subject"], condition["state"])) if condition else None
    args = tuple(arg.strip() for arg in inside.split(",")) if inside else ()
    return Call(name, args) if all(_ARG.match(arg) for arg in args) else None


def loops(text: str, longest: int = 4) -> bool:
    """Whether the last complete lines repeat the ones just before them, as a greedy model going round in
    circles does ("whisk(x); stir(x); whisk(x); stir(x) …"); comments and the unfinished line are ignored."""
    lines = [line.strip() for line in text.split("\n")[:-1] if line.strip() and not line.strip().startswith("#")]
    return any(len(lines) >= 2 * k and lines[-k:] == lines[-2 * k:-k] for k in range(1, longest + 1))


def without_loops(calls: tuple[Call, ...]) -> tuple[Call, ...]:
    """The calls up to where they start repeating themselves."""
    kept: list[Call] = []
    for call in calls:
        kept.append(call)
        text = "".join(f"{c.text()}\n" for c in kept)
        if loops(text):
            for k in range(1, 5):
                if len(kept) >= 2 * k and kept[-k:] == kept[-2 * k:-k]:
                    return tuple(kept[:-k])
    return tuple(kept)


def is_empty(body: str) -> bool:
    """Whether a body has no line at all: how the library records that the model wrote no admissible plan."""
    return not body.strip()


def write_body(calls: tuple[Call, ...]) -> str:
    return "\n".join(call.text() for call in calls)


def placeholders(action: Action) -> dict[str, str]:
    """Each parameter's placeholder → its value in this action: {"$what": "egg", "$time": "cold"}."""
    return bind(action.signature, tuple(parameter.value for parameter in action.parameters))


def bind(signature: tuple[str, ...], arguments: tuple[str, ...]) -> dict[str, str]:
    """Placeholders of a signature ("what", "what", "where") → $what, $what2, $where, bound to the arguments."""
    seen: Counter[str] = Counter()
    bound = {}
    for category, argument in zip(signature, arguments):
        seen[category] += 1
        bound[f"${category}{seen[category] if seen[category] > 1 else ''}"] = argument
    return bound


def parametrize(calls: tuple[Call, ...], action: Action) -> str:
    """The body with the action's values replaced by placeholders, as stored in the library."""
    by_value: dict[str, str] = {}
    for placeholder, value in placeholders(action).items():
        by_value.setdefault(value, placeholder)
    return write_body(tuple(Call(c.name, tuple(by_value.get(a, a) for a in c.args)) for c in calls))


def instantiate(body: str, values: dict[str, str]) -> tuple[Call, ...] | None:
    """A stored body with its placeholders filled, or None when it does not fit (an unbound placeholder,
    a line that is not a call)."""
    calls, unread = read_body(body)
    if unread or any(arg.startswith("$") and arg not in values for call in calls for arg in call.args):
        return None
    return tuple(Call(call.name, tuple(values.get(arg, arg) for arg in call.args)) for call in calls)
