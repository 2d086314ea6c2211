"""Which library entries can serve an action whose exact key (verb, signature) has none, and how.

The library is keyed by verb and signature, so `add(flour, sugar, bowl)` finds nothing under
add(what, what, where) even when add(what, where) is learnt. An entry serves such an action only when it is
the same action, never silently:

* the same verb, or two verbs the verb-effect table reads as one of its rows (`known_verb`: `stir_in` has no
  row of its own, so the table reads it as `stir`). A verb with a row of its own is its own action: two rows
  are never merged, however alike their effects;
* every placeholder its body uses can be bound from the action's arguments of the same role. What the action
  is done to (its whats) and where it goes (its wheres) are never left out: the body binds them all ($what,
  $what2 … in order), or, for the whats, it uses $what alone and is written out once per what, the other
  roles bound the same (distributed over the objects of "add the flour and the sugar to the bowl"). An
  argument of another role the body does not use (a how, a time, a temperature) is ignored, and the reuse
  says so.

Candidates are the live entries with a plan (approved ones only in lab mode), as `Library.live` gives them;
the best comes first: the exact key (which `Library.lookup` finds itself), then the action's own verb before
another verb of its table row, then fewest ignored arguments, then a body bound once before one distributed,
then the oldest entry. Every reuse carries its reasons, for the report, the JSON and the app.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from cook2ltl.domain.actions import Action, Call
from cook2ltl.library.entry import LibraryEntry, Status
from cook2ltl.reduce.body import instantiate, read_body
from cook2ltl.world.effects import known_verb

KEPT = ("what", "where")  # what an action is done to and where it goes: never left out of a reuse
SPREAD = "what"  # the role a body of one such argument is distributed over
_PLACEHOLDER = re.compile(r"\$(?P<role>[a-z]+?)(?P<index>[2-9]|[1-9][0-9]+)?\Z")


@dataclass(frozen=True)
class Reuse:
    """An entry serving an action it was not learnt for: which entry, its key, and why it may."""

    entry_id: int
    verb: str
    signature: tuple[str, ...]
    reasons: tuple[str, ...]

    def json(self) -> dict:
        return {"entry": self.entry_id, "verb": self.verb, "signature": list(self.signature),
                "reasons": list(self.reasons)}

    def text(self) -> str:
        """`entry 3 stir(what): the verb-effect table reads stir_in as stir`."""
        return f"entry {self.entry_id} {self.verb}({', '.join(self.signature)})" + (
            f": {'; '.join(self.reasons)}" if self.reasons else "")


@dataclass(frozen=True)
class Fit:
    """How an entry serves an action: the reuse as shown, and the entry's body instantiated for the action."""

    reuse: Reuse
    entry: LibraryEntry
    body: tuple[Call, ...]
    rank: tuple[int, ...]


def same_action(verb: str, other: str, table: dict | None = None) -> str | None:
    """Why two verbs are one action ("" for the same verb), or None when they are not: the table's row both
    resolve to, through `known_verb`."""
    if verb == other:
        return ""
    row = known_verb(verb, table)
    if row is None or row != known_verb(other, table):
        return None
    shown = verb if other == row else f"{verb} and {other}" if verb != row else other
    return f"the verb-effect table reads {shown} as {row}"


def reuses(action: Action, entries: Iterable[LibraryEntry], approved_only: bool = False,
           table: dict | None = None) -> tuple[Fit, ...]:
    """The entries that can serve `action`, best first (see the module's docstring)."""
    fits = [fit for entry in entries if _usable(entry, approved_only)
            if (fit := fit_entry(action, entry, table)) is not None]
    return tuple(sorted(fits, key=lambda fit: fit.rank))


def fit_entry(action: Action, entry: LibraryEntry, table: dict | None = None) -> Fit | None:
    """How `entry` serves `action`, or None when it cannot (another action, a placeholder left unbound, a
    what or where left out, a body that is not calls)."""
    verb_reason = same_action(action.verb, entry.verb, table)
    used = _used(entry.body) if verb_reason is not None else None
    binding = _binding(action, used) if used is not None else None
    if binding is None:
        return None
    bound, spread, ignored = binding
    bodies = [instantiate(entry.body, bound | ({_placeholder(SPREAD, 1): what} if what else {}))
              for what in spread or [""]]
    if any(body is None for body in bodies) or not any(bodies):
        return None
    reasons = [verb_reason] if verb_reason else []
    if spread:
        reasons.append(f"distributed over {len(spread)} objects: {', '.join(spread)}")
    reasons += [f"ignores {role}: {', '.join(names)}" for role, names in ignored.items()]
    if not reasons and entry.signature != action.signature:
        reasons.append(f"its body needs only {', '.join(used) or 'no argument'}")
    exact = (entry.verb, entry.signature) == (action.verb, action.signature)
    rank = (int(not exact), int(bool(verb_reason)), sum(map(len, ignored.values())), int(bool(spread)), entry.id)
    reuse = Reuse(entry.id, entry.verb, entry.signature, tuple(reasons))
    return Fit(reuse, entry, tuple(call for body in bodies for call in body), rank)


def _binding(action: Action, used: dict[str, set[int]]
             ) -> tuple[dict[str, str], list[str], dict[str, list[str]]] | None:
    """The action's arguments bound to the placeholders the body uses: the bound values, the whats the body is
    distributed over (none: bound once), and per role the arguments it ignores; None when it cannot be."""
    by_role: dict[str, list[tuple[str, str]]] = {}
    for parameter in action.parameters:
        by_role.setdefault(parameter.category, []).append((parameter.value, parameter.name))
    bound: dict[str, str] = {}
    spread: list[str] = []
    ignored: dict[str, list[str]] = {}
    for role in dict.fromkeys([*by_role, *used]):
        have, need = by_role.get(role, []), used.get(role, set())
        if any(index > len(have) for index in need):
            return None  # a placeholder the action cannot fill
        if role in KEPT and need != set(range(1, len(have) + 1)):
            if role != SPREAD or need != {1} or len(have) < 2:
                return None  # the body would leave a what or a where out
            spread = [value for value, _ in have]
            continue
        bound |= {_placeholder(role, index): have[index - 1][0] for index in need}
        left = [name for index, (_, name) in enumerate(have, start=1) if index not in need]
        if left:
            ignored[role] = left
    return bound, spread, ignored


def _used(body: str) -> dict[str, set[int]] | None:
    """The placeholders a body uses, by role: {"what": {1, 2}, "where": {1}}; None for a body that is not calls
    or names a placeholder no signature makes."""
    calls, unread = read_body(body)
    if unread:
        return None
    used: dict[str, set[int]] = {}
    for argument in (a for call in calls for a in call.args if a.startswith("$")):
        match = _PLACEHOLDER.match(argument)
        if match is None:
            return None
        used.setdefault(match["role"], set()).add(int(match["index"] or 1))
    return used


def _placeholder(role: str, index: int) -> str:
    """As `reduce.body.bind` names them: $what, $what2, $what3 …"""
    return f"${role}{index if index > 1 else ''}"


def _usable(entry: LibraryEntry, approved_only: bool) -> bool:
    """As `Library.lookup` and `live` filter: not rejected (approved in lab mode), and with a plan."""
    status = Status(entry.status)
    return entry.has_plan and (status == Status.APPROVED if approved_only else status != Status.REJECTED)
