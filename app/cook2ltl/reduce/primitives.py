"""Primitive sets 𝒜 as data: assets/primitives/<name>.toml, or any TOML file a lab writes for its robot.

    name = "my-robot"
    examples = "my-robot-examples.txt"      # example functions for the prompt, relative to this file
    objects = ["pot", "stovetop", ...]     # what the robot may touch, besides the recipe's own objects
    states = ["boiled", "cold", ...]       # what a wait may wait for
    [primitives]
    pick_up = ["what"]                     # parameters in call order; `condition` is `subject == state`
    put = ["what", "where"]
    wait = ["condition"]

Names of primitives, parameters, objects and states are lower-case identifiers: they become words of the
decoding grammar. The file, its examples, its domain and its kitchen are read with bounds (files.py).
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

from pydantic import Field, StringConstraints, field_validator

from cook2ltl import files, paths
from cook2ltl.domain.actions import CONDITION, Primitive, PrimitiveSet, WorldSpec
from cook2ltl.errors import UserError
from cook2ltl.toml_models import FileName, Identifier, PddlName, Table, flag, validated

BUILT_IN = ("recipe", "ai2thor")
THOR_KITCHENS = "thor"  # a [world] kitchen: the 30 AI2-THOR kitchens
HINT = "see assets/primitives/recipe.toml for the format."
SET_BYTES = 1_000_000  # the paper's sets are under 3 kB
EXAMPLES_BYTES = 200_000  # the examples go into every prompt: the paper's are 1 kB
MAX_PRIMITIVES, MAX_PARAMETERS, MAX_OBJECTS, MAX_STATES = 200, 8, 2000, 500

SetName = Annotated[str, StringConstraints(pattern=r"^[A-Za-z0-9][A-Za-z0-9_.-]*$", max_length=64),
                    Field(description="a name such as my-robot (letters, digits, _, . and -)")]
KitKey = Annotated[str, StringConstraints(pattern=r"^(\*|[a-z][a-z0-9_-]*)$", max_length=64),
                   Field(description='a goal predicate, or "*" for every goal')]

Parameters = Annotated[list[Identifier], Field(max_length=MAX_PARAMETERS, description=(
    f'a list of at most {MAX_PARAMETERS} parameter names in call order, e.g. ["what", "where"]'))]


class WorldTable(Table):
    """[world]: domain = "x.pddl", kitchen = "k.toml" or "thor", kit = [objects the planner may use],
    planner = true (false: plans are checked, never completed), liquids = "filled-with" (the predicate
    telling which container a liquid fills, when liquids are not `in` things), [world.states] word = "predicate"."""

    domain: FileName = Field(description='the PDDL domain file, e.g. "domain.pddl"')
    kitchen: FileName = Field(THOR_KITCHENS, description='a kitchen file, or "thor" for the AI2-THOR kitchens')
    states: dict[Identifier, PddlName] = Field({}, max_length=MAX_STATES,
                                               description='a table of state words and their predicates')
    kit: dict[KitKey, list[PddlName]] | None = Field(
        None, max_length=MAX_STATES, description="a list of object names, or a table of them by goal predicate")
    planner: bool = flag(True)
    liquids: PddlName | None = Field(None, description='the predicate a liquid fills its container by, such as '
                                                       '"filled-with"')

    @field_validator("kit", mode="before")
    @classmethod
    def _for_every_goal(cls, kit: object) -> object:
        return {"*": kit} if isinstance(kit, list) else kit


class PrimitiveSetFile(Table):
    name: SetName | None = None
    examples: FileName = Field(description="the file of the prompt's example functions, beside this one")
    objects: list[Identifier] = Field([], max_length=MAX_OBJECTS,
                                      description=f"a list of at most {MAX_OBJECTS} lower-case identifiers")
    states: list[Identifier] = Field([], max_length=MAX_STATES,
                                     description=f"a list of at most {MAX_STATES} lower-case identifiers")
    primitives: dict[Identifier, Parameters] = Field(
        min_length=1, max_length=MAX_PRIMITIVES,
        description=f'a table of 1 to {MAX_PRIMITIVES} primitives, each with at most {MAX_PARAMETERS} parameters, '
                    'e.g. put = ["what", "where"]')
    world: WorldTable | None = Field(None, description="a table")
    thor: dict[Identifier, Identifier] = Field(
        {}, max_length=MAX_PRIMITIVES,
        description='a table of primitives and what each does in a THOR kitchen, e.g. cut = "slice"')


def load_primitives(choice: str) -> PrimitiveSet:
    """A built-in set by name (recipe, ai2thor) or a TOML file by path."""
    if choice in BUILT_IN:
        path = paths.assets_dir() / "primitives" / f"{choice}.toml"
    else:
        path = paths.user_path(choice, "The primitive set")
    try:
        raw = files.read_toml(path, SET_BYTES, "primitive set", HINT)
    except files.MissingFile:
        raise UserError(f"No primitive set {paths.shown(choice)}.",
                        f"use {' or '.join(BUILT_IN)}, or the path of a TOML file.") from None
    return _primitive_set(validated(PrimitiveSetFile, raw, path, HINT), path)


def _primitive_set(file: PrimitiveSetFile, path: Path) -> PrimitiveSet:
    def bad(message: str) -> UserError:
        return UserError(f"{paths.shown(path)}: {message}", HINT)

    primitives = []
    for name, params in file.primitives.items():
        if CONDITION in params and params != [CONDITION]:
            raise bad(f"primitive {name!r}: a `condition` parameter must be its only one.")
        primitives.append(Primitive(name, tuple(params)))
    objects, states = tuple(dict.fromkeys(file.objects)), tuple(dict.fromkeys(file.states))
    clash = set(states) & set(file.primitives)
    if clash:
        raise bad(f"{', '.join(sorted(clash))} is both a primitive and a state; a state atom would read as the action.")
    if not objects:
        raise bad("`objects` is empty: list what the robot may handle besides a recipe's own objects.")
    strangers = sorted(set(file.thor) - set(file.primitives))
    if strangers:
        raise bad(f"[thor] names {', '.join(strangers)}, which the set's [primitives] do not have.")
    examples = files.read_text(_beside(path, file.examples, "examples"), EXAMPLES_BYTES, "examples file", HINT)
    world = None if file.world is None else _world(file.world, path)
    return PrimitiveSet(file.name or path.stem, tuple(primitives), objects, states, examples.expandtabs(4), path,
                        world, tuple(file.thor.items()))


def _world(table: WorldTable, path: Path) -> WorldSpec:
    domain = _beside(path, table.domain, "[world] domain")
    if not files.is_regular_file(domain):
        raise UserError(f"{paths.shown(path)}: the domain file {paths.shown(domain)} is missing or not a regular "
                        "file.", HINT)
    kitchen = None if table.kitchen == THOR_KITCHENS else _beside(path, table.kitchen, "[world] kitchen")
    kit = None if table.kit is None else tuple((goal, tuple(names)) for goal, names in table.kit.items())
    return WorldSpec(domain, kitchen, tuple(sorted(table.states.items())), kit, table.planner, table.liquids)


def _beside(path: Path, name: str, key: str) -> Path:
    """A file the set names, relative to the set's own file (or from ~, or absolute)."""
    return path.parent / paths.user_path(name, f"{paths.shown(path)}: {key}")
