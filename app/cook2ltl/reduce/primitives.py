"""Primitive sets 𝒜 as data: assets/primitives/<name>.toml, or any TOML file a lab writes for its robot.

    name = "my-robot"
    examples = "my-robot-examples.txt"      # example functions for the prompt, relative to this file
    objects = ["pot", "stovetop", ...]     # what the robot may touch, besides the recipe's own objects
    states = ["boiled", "cold", ...]       # what a wait may wait for
    [primitives]
    pick_up = ["what"]                     # parameters in call order; `condition` is `subject == state`
    put = ["what", "where"]
    wait = ["condition"]
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

from cook2ltl import paths
from cook2ltl.errors import UserError
from cook2ltl.reduce.model import CONDITION, Primitive, PrimitiveSet, WorldSpec

BUILT_IN = ("recipe", "ai2thor")
IDENTIFIER = re.compile(r"[a-z][a-z0-9_]*\Z")
PDDL_NAME = re.compile(r"[a-z][a-z0-9_-]*\Z")
VALUE = re.compile(r"[a-z0-9][a-z0-9_]*\Z")
THOR_KITCHENS = "thor"  # a [world] kitchen: the 30 AI2-THOR kitchens


def load_primitives(choice: str) -> PrimitiveSet:
    """A built-in set by name (recipe, ai2thor) or a TOML file by path."""
    path = paths.assets_dir() / "primitives" / f"{choice}.toml" if choice in BUILT_IN else Path(choice).expanduser()
    if not path.is_file():
        raise UserError(f"No primitive set {choice!r}.", f"use {' or '.join(BUILT_IN)}, or the path of a TOML file.")
    try:
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise UserError(f"{path} is not valid TOML: {error}", "see assets/primitives/recipe.toml for the format.") from error
    return _primitive_set(raw, path)


def _primitive_set(raw: dict, path: Path) -> PrimitiveSet:
    def bad(message: str) -> UserError:
        return UserError(f"{path}: {message}", "see assets/primitives/recipe.toml for the format.")

    table = raw.get("primitives")
    if not isinstance(table, dict) or not table:
        raise bad("no [primitives] table.")
    primitives = []
    for name, params in table.items():
        if not IDENTIFIER.match(name):
            raise bad(f"primitive {name!r} is not a lower-case identifier (use pick_up, not 'pick up').")
        if not isinstance(params, list) or not all(isinstance(p, str) and IDENTIFIER.match(p) for p in params):
            raise bad(f"primitive {name!r}: parameters must be a list of names, e.g. [\"what\", \"where\"].")
        if CONDITION in params and params != [CONDITION]:
            raise bad(f"primitive {name!r}: a `condition` parameter must be its only one.")
        primitives.append(Primitive(name, tuple(params)))
    objects, states = _words(raw, "objects", bad), _words(raw, "states", bad)
    clash = set(states) & {p.name for p in primitives}
    if clash:
        raise bad(f"{', '.join(sorted(clash))} is both a primitive and a state; a state atom would read as the action.")
    if not objects:
        raise bad("`objects` is empty: list what the robot may handle besides a recipe's own objects.")
    examples_name = raw.get("examples")
    if not isinstance(examples_name, str):
        raise bad("no `examples` file named (the prompt's example functions).")
    examples_path = path.parent / examples_name
    try:
        examples = examples_path.read_text(encoding="utf-8").expandtabs(4)
    except OSError as error:
        raise bad(f"cannot read the examples file {examples_path}: {error.strerror}.") from error
    name = raw.get("name", path.stem)
    return PrimitiveSet(str(name), tuple(primitives), objects, states, examples, path, _world(raw, path, bad))


def _world(raw: dict, path: Path, bad) -> WorldSpec | None:
    """[world]: domain = "x.pddl", kitchen = "k.toml" or "thor", kit = [objects the planner may use],
    planner = true (false: plans are checked, never completed), liquids = "filled-with" (the predicate
    telling which container a liquid fills, when liquids are not `in` things), [world.states] word = "predicate"."""
    table = raw.get("world")
    if table is None:
        return None
    if not isinstance(table, dict) or not isinstance(table.get("domain"), str):
        raise bad("[world] needs `domain = \"file.pddl\"`, the set's PDDL domain.")
    kitchen = table.get("kitchen", THOR_KITCHENS)
    states = table.get("states", {})
    if not isinstance(kitchen, str) or not isinstance(states, dict) or not all(
            isinstance(v, str) and IDENTIFIER.match(k) for k, v in states.items()):
        raise bad("[world] kitchen must be a file name or \"thor\", and [world.states] map words to predicates.")
    domain = path.parent / table["domain"]
    if not domain.is_file():
        raise bad(f"the domain file {domain} does not exist.")
    where = None if kitchen == THOR_KITCHENS else path.parent / kitchen
    kit = table.get("kit")
    kit = {"*": kit} if isinstance(kit, list) else kit
    if kit is not None and not (isinstance(kit, dict) and all(
            isinstance(v, list) and all(isinstance(k, str) for k in v) for v in kit.values())):
        raise bad("[world] kit must be a list of object names, or a table of them by goal predicate.")
    planner = table.get("planner", True)
    if not isinstance(planner, bool):
        raise bad("[world] planner must be true or false.")
    liquid_fill = table.get("liquids")
    if liquid_fill is not None and not (isinstance(liquid_fill, str) and PDDL_NAME.match(liquid_fill)):
        raise bad("[world] liquids must name a predicate, such as \"filled-with\".")
    kit = tuple((p, tuple(v)) for p, v in kit.items()) if kit is not None else None
    return WorldSpec(domain, where, tuple(sorted(states.items())), kit, planner, liquid_fill)


def _words(raw: dict, key: str, bad) -> tuple[str, ...]:
    words = raw.get(key, [])
    if not isinstance(words, list) or not all(isinstance(w, str) and VALUE.match(w) for w in words):
        raise bad(f"`{key}` must be a list of lower-case identifiers such as baking_pan.")
    return tuple(dict.fromkeys(words))
