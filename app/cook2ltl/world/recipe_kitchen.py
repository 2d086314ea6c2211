"""The state a recipe starts in, for a world whose kitchen is a TOML file (assets/kitchens/recipe-kitchen.toml).

Every object of the file with its kinds, where it stands, and every other name the recipe uses: of the kinds
of its head noun where the file has that (a medium_saucepan is a saucepan), else as an ingredient on the
countertop (a liquid one poured from its carton, never held).
"""

from __future__ import annotations

import tomllib
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from cook2ltl.errors import UserError
from cook2ltl.world.logic import Fact, State
from cook2ltl.world.world import kept_facts

COUNTER = "countertop"


@dataclass(frozen=True)
class KitchenFile:
    kinds: dict[str, tuple[str, ...]]
    start: dict[str, str]  # object → where it stands ("" for nowhere); the rest stand on the countertop
    ingredient_kinds: tuple[str, ...]
    liquids: frozenset[str]
    meltable: frozenset[str]
    kit: tuple[str, ...]  # what the planner may use besides the objects a goal names

    def kinds_of(self, name: str) -> tuple[str, ...]:
        name = self.known(name)
        if name in self.kinds:
            return self.kinds[name]
        last = name.rsplit("_", 1)[-1]
        if last in self.liquids:
            return ("food", "liquid")
        return (*self.ingredient_kinds, *(("meltable",) if last in self.meltable else ()))

    def place_of(self, name: str) -> str:
        if self.known(name) in self.start:
            return self.start[self.known(name)]
        return "" if "liquid" in self.kinds_of(name) else COUNTER

    def known(self, name: str) -> str:
        """The kitchen's own name for `name`: itself, else its head noun when the kitchen has that (a
        medium_saucepan is a saucepan, a large_pot a pot); else `name`, an ingredient."""
        last = name.rsplit("_", 1)[-1]
        return name if name in self.kinds or last not in self.kinds else last


@cache
def read_kitchen(path: Path) -> KitchenFile:
    try:
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
        ingredients = raw.get("ingredients", {})
        return KitchenFile(
            {name: tuple(kinds) for name, kinds in raw["kinds"].items()},
            dict(raw.get("start", {})),
            tuple(ingredients.get("kinds", ("food", "portable"))),
            frozenset(ingredients.get("liquids", ())),
            frozenset(ingredients.get("meltable", ())),
            tuple(raw.get("planning", {}).get("kit", ())),
        )
    except (OSError, tomllib.TOMLDecodeError, KeyError, TypeError, AttributeError) as error:
        raise UserError(f"{path} is not a kitchen file cook2ltl can read: {error}",
                        "see assets/kitchens/recipe-kitchen.toml for the format.") from error


def kitchen_state(path: Path, names: Iterable[str]) -> State:
    kitchen = read_kitchen(path)
    objects = tuple(dict.fromkeys((*kitchen.kinds, *names)))
    facts: set[Fact] = {("hand-empty",)}
    for name in objects:
        facts.update((kind, name) for kind in kitchen.kinds_of(name))
        place = kitchen.place_of(name)
        if place and place != name:
            facts.add(("in", name, place))
    return State(objects, frozenset(facts | kept_facts(facts)))

