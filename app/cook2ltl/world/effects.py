"""Intended effects: the states an action must leave, from the verb-effect table (assets/effects.toml).

    [verbs]
    boil = ["boiled(what)"]
    refrigerate = ["cold(what)", "in(what, fridge)"]

An atom's arguments are the action's slots (what, where, how: one atom per object of the slot) or kitchen
objects. A verb missing from the table falls back to its first word (`stir_in` → stir). "done" and "ready"
are never effects: the world cannot observe them.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from functools import cache
from itertools import product
from pathlib import Path

from cook2ltl import files, paths
from cook2ltl.domain.actions import Action
from cook2ltl.errors import UserError
from cook2ltl.paths import shown
from cook2ltl.world.logic import Fact, State
from cook2ltl.world.world import World

SLOTS = ("what", "where", "how")
NEVER = frozenset({"done", "ready"})
SOURCE_WORDS = ("from ", "out of ", "off of ", "off ")
EFFECTS_BYTES = 1_000_000  # the table is 10 kB
_ATOM = re.compile(r"\s*([a-z][a-z0-9_-]*)\(([a-z0-9_, ]*)\)\s*\Z")

Template = tuple[str, tuple[str, ...]]  # predicate, arguments (slots or objects)


def effects_file() -> Path:
    return paths.assets_dir() / "effects.toml"


@cache
def verb_table(path: Path | None = None) -> dict[str, tuple[Template, ...]]:
    path = path or effects_file()
    hint = "it is a [verbs] table: boil = [\"boiled(what)\"]."
    verbs = files.read_toml(path, EFFECTS_BYTES, "verb-effect table", hint).get("verbs")
    if not isinstance(verbs, dict) or not all(isinstance(atoms, list) for atoms in verbs.values()):
        raise UserError(f"{shown(path)} has no [verbs] table of lists of atoms.", hint)
    return {verb: tuple(_template(verb, atom, path) for atom in atoms) for verb, atoms in verbs.items()}


def parse_template(text: str) -> Template:
    """One effect atom such as `in(what, fridge)`: the table's syntax, also for effects a library entry keeps."""
    match = _ATOM.match(text) if isinstance(text, str) else None
    if match is None:
        raise ValueError(f"{text!r} is not an effect atom such as boiled(what)")
    if match[1] in NEVER:
        raise ValueError(f"{text!r}: {match[1]} is never an effect (the world cannot observe it)")
    return match[1], tuple(arg.strip() for arg in match[2].split(",") if arg.strip())


def _template(verb: str, text: str, path: Path) -> Template:
    try:
        return parse_template(text)
    except ValueError as error:
        raise UserError(f"{shown(path)}: {verb} = {text!r} is not an effect atom such as boiled(what).",
                        "effects are observable states; done and ready are never effects.") from error


def known_verb(verb: str, table: dict[str, tuple[Template, ...]] | None = None) -> str | None:
    table = verb_table() if table is None else table
    if verb in table:
        return verb
    first = verb.split("_", 1)[0]
    return first if first in table else None


def table_effect(verb: str) -> tuple[Template, ...] | None:
    """The verb's effect templates from the table (or its first word's); None when the table lacks it."""
    table = verb_table()
    known = known_verb(verb, table)
    return None if known is None else table[known]


def intended_effect(action: Action, world: World, state: State,
                    templates: Sequence[Template] | None = None) -> tuple[Fact, ...] | None:
    """The facts `action` must make true, in `world`'s predicates, over objects of `state`: `templates` (an
    entry's own), else the table's; None when the table does not know the verb. Atoms the world cannot
    observe, whose objects it lacks, or that no action could make true there (`in(mix, ribs)` in THOR, where
    food holds nothing) are left out."""
    templates = table_effect(action.verb) if templates is None else templates
    if templates is None:
        return None
    slots = {slot: [p.value for p in action.parameters if p.category == slot and not _source(p.text)]
             for slot in SLOTS}
    facts: dict[Fact, None] = {}
    for predicate, args in templates:
        choices = [slots[a] if a in SLOTS else [a] for a in args]
        for values in product(*choices):
            if all(v in state.objects for v in values) and len(set(values)) == len(values):
                observed = _observed(world, state, predicate, values, slots)
                facts |= dict.fromkeys(fact for fact in observed if world.possible(state, fact))
    return tuple(facts)


def cast(actions: Sequence[Action], world: World) -> tuple[list[str], set[str], dict[str, set[str]]]:
    """What a recipe asks of its names, for choosing the kitchen's things: the names, in order; those things
    are put into; and the states of the world each is to take by the table's effects (the chicken is fried:
    cooked)."""
    names = [o for action in actions for o in action.objects]
    places = {p.value for action in actions for p in action.parameters if p.category == "where"}
    asks: dict[str, set[str]] = {}
    for action in actions:
        for predicate, args in table_effect(action.verb) or ():
            state = world.predicate(predicate) if len(args) == 1 and args[0] in SLOTS else None
            if state is None:
                continue
            for p in action.parameters:
                if p.category == args[0]:
                    asks.setdefault(p.value, set()).add(state)
    return names, places, asks


def _source(text: str) -> bool:
    """Whether an argument names where something comes from ("from a lemon", "out of the pot"), which is no
    place it ends in."""
    return text.lower().lstrip().startswith(SOURCE_WORDS)


def _observed(world: World, state: State, predicate: str, values: tuple[str, ...],
              slots: dict[str, list[str]]) -> tuple[Fact, ...]:
    """An atom in the world's own predicates. Where the world tells a liquid by the container it fills (THOR),
    a liquid in a container is that container filled with it, and a liquid's state is its container's
    (boiled water is a hot kettle full of water): the action's container, else the one already holding it."""
    liquids = [v for v in values if ("liquid", v) in state.facts] if world.liquid_fill else []
    if liquids and predicate == "in" and values[0] in liquids:
        return ((world.liquid_fill, values[1], values[0]),)
    if liquids and len(values) == 1:
        container = _container_of(world, state, values[0], slots)
        if container is None:
            return ()
        held = _observed(world, state, predicate, (container,), slots)
        return (*held, (world.liquid_fill, container, values[0])) if held else ()
    name = world.predicate(predicate) if len(values) == 1 else predicate
    if name is None or world.domain.predicates.get(name) != len(values):
        return ()
    return ((name, *values),)


def _container_of(world: World, state: State, liquid: str, slots: dict[str, list[str]]) -> str | None:
    named = [v for slot in ("where", "how") for v in slots[slot] if ("fillable", v) in state.facts]
    holding = [f[1] for f in state.by_predicate.get(world.liquid_fill, ()) if f[2] == liquid]
    return next(iter(named + sorted(holding)), None)


def fact_text(fact: Fact) -> str:
    return f"{fact[0]}({', '.join(fact[1:])})"


def template_text(template: Template) -> str:
    return fact_text((template[0], *template[1]))
