"""The intended effect a library entry keeps: the atoms that must hold after its plan, as templates over the
action's slots in the syntax of the verb-effect table (`boiled(what)`, `in(what, fridge)`; see
`world.effects`). Stored with the entry, so an entry for a verb the table lacks keeps the effect a model or
a person wrote. None: not recorded (an entry from before effects were kept); empty: nothing observable to
reach (as the table's `peel = []`).
"""

from __future__ import annotations

from collections.abc import Sequence
from enum import Enum

from cook2ltl.errors import UserError
from cook2ltl.world.effects import parse_template, template_text

HINT = ("write atoms such as boiled(what) or in(what, fridge): a predicate over the action's slots (what, where, "
        "how) or kitchen objects; done and ready are never effects.")


class Keep(Enum):
    KEEP = "keep"


KEEP = Keep.KEEP  # Library.edit(effect=KEEP): the entry keeps the effect it has


def checked_effect(effect: Sequence[str] | None, where: str = "effect") -> tuple[str, ...] | None:
    """The effect as stored: each atom checked, written one way (`in(what, fridge)`), duplicates dropped.
    A bad atom is a UserError that starts with `where`."""
    if effect is None:
        return None
    if isinstance(effect, str):  # a lone string would be read letter by letter
        raise TypeError("an effect is a sequence of atoms, not one string")
    atoms: dict[str, None] = {}
    for text in effect:
        try:
            atoms[template_text(parse_template(text))] = None
        except ValueError as error:
            raise UserError(f"{where}: {error}.", HINT) from error
    return tuple(atoms)


def shown_effect(effect: tuple[str, ...] | None) -> str:
    if effect is None:
        return "not recorded"
    return ", ".join(effect) if effect else "none (nothing to reach)"
