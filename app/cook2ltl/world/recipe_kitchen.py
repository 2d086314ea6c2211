"""The state a recipe starts in, for a world whose kitchen is a TOML file (assets/kitchens/recipe-kitchen.toml).

Every object of the file with its kinds, where it stands, and every other name the recipe uses: of the kinds
of its head noun where the file has that (a medium_saucepan is a saucepan), else as an ingredient on the
countertop (a liquid one poured from its carton, never held).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Annotated

from pydantic import Field, StringConstraints

from cook2ltl import files
from cook2ltl.toml_models import Identifier, PddlName, Table, validated
from cook2ltl.world.logic import Fact, State
from cook2ltl.world.world import kept_facts

COUNTER = "countertop"
KITCHEN_BYTES = 1_000_000  # the recipe kitchen is 4 kB
MAX_NAMES = 5000
Place = Annotated[str, StringConstraints(pattern=r"^([a-z][a-z0-9_]*)?$", max_length=64),
                  Field(description='a kitchen object, or "" for nowhere')]
Kinds = Annotated[list[PddlName], Field(max_length=MAX_NAMES, description="a list of kinds such as portable")]


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


class _Ingredients(Table):
    kinds: list[PddlName] = Field(["food", "portable"], max_length=MAX_NAMES, description="a list of kinds")
    liquids: list[Identifier] = Field([], max_length=MAX_NAMES, description="a list of head nouns")
    meltable: list[Identifier] = Field([], max_length=MAX_NAMES, description="a list of head nouns")


class _Planning(Table):
    kit: list[Identifier] = Field([], max_length=MAX_NAMES, description="a list of kitchen objects")


class _KitchenFile(Table):
    kinds: dict[Identifier, Kinds] = Field(
        max_length=MAX_NAMES, description='a table of objects and their kinds, e.g. pot = ["portable", "vessel"]')
    start: dict[Identifier, Place] = Field({}, max_length=MAX_NAMES, description="a table of objects and places")
    ingredients: _Ingredients = Field(_Ingredients(), description="a table")
    planning: _Planning = Field(_Planning(), description="a table")


@cache
def read_kitchen(path: Path) -> KitchenFile:
    hint = "see assets/kitchens/recipe-kitchen.toml for the format."
    file = validated(_KitchenFile, files.read_toml(path, KITCHEN_BYTES, "kitchen file", hint), path, hint)
    ingredients = file.ingredients
    return KitchenFile({name: tuple(kinds) for name, kinds in file.kinds.items()}, dict(file.start),
                       tuple(ingredients.kinds), frozenset(ingredients.liquids), frozenset(ingredients.meltable),
                       tuple(file.planning.kit))


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

