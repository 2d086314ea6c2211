"""The kitchen a plan is checked in: the THOR kitchen that has most of its objects, and stand-ins for the rest.

A recipe names things no THOR kitchen has (penne, a saucepan, an oven). Rather than fail every such plan
with "object not found", which no repair could fix, each name is bound before the run to an object of a
fitting THOR type, so THOR's own rules judge the plan's order of actions:

* a name THOR knows (`pot`, `fridge`, `stove_burner`, `sink`) stands for itself;
* a kitchen word of `STAND_INS` stands for the first of its types the kitchen has
  (`saucepan` → a Pot, `oven` → a Microwave: closed, switched, heats what is put in it);
* THOR's liquids (water, coffee, wine) are not objects: putting or pouring one fills the container;
* a word of `NO_COUNTERPART` (a blender, a grater) has nothing that could stand for it: the plan is
  not checked, and says why;
* any other name is an ingredient and stands for a food object the plan does not name itself
  (a Potato, an Apple …, then a small thing the agent can carry): it must be picked up before it is put
  somewhere, cut with a knife in hand; but an ingredient that things are put or poured into (the mix, the
  batter) is a container to the kitchen: it stands for a Bowl, a Pot …;
* a name beyond what the kitchen has of its type (a second bowl) stands for another container or food.

The kitchen chosen is the one of the 30 where the most names find an object (ties: the lowest number).
A whole recipe gets one such kitchen (`best_frame`): the world model binds the recipe's names in it the
same way, so the kitchen check and the world model judge the same objects.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Collection, Iterable, Mapping
from dataclasses import dataclass
from functools import cache

from cook2ltl.domain.actions import TIMER, Call
from cook2ltl.thor_types import load_type_rules
from cook2ltl.world.thor_kitchens import scene_names, scene_objects
from cook2ltl.world.thor_names import shut_away, types_for

# Kitchen words of recipes and the THOR types that can stand for them, best first.
STAND_INS: Mapping[str, tuple[str, ...]] = {
    "saucepan": ("Pot", "Pan"), "stock_pot": ("Pot",), "skillet": ("Pan", "Pot"), "frying_pan": ("Pan",),
    "wok": ("Pan", "Pot"), "griddle": ("Pan",),
    "baking_pan": ("Plate",), "baking_dish": ("Plate",), "baking_sheet": ("Plate",), "casserole": ("Plate",),
    "dish": ("Plate",), "tray": ("Plate",), "platter": ("Plate",), "cutting_board": ("Plate",),
    "mixing_bowl": ("Bowl",), "colander": ("Bowl",), "sieve": ("Bowl",), "strainer": ("Bowl",),
    "measuring_cup": ("Cup", "Mug"), "glass": ("Cup",),
    "oven": ("Microwave",), "freezer": ("Fridge",),
    "whisk": ("Spatula", "Spoon", "Fork"), "wooden_spoon": ("Spoon", "Spatula"), "tongs": ("Spatula", "Fork"),
}  # fmt: skip
# Kitchen words no THOR type can stand for: a plan that uses one is not checked.
NO_COUNTERPART = frozenset(
    "blender mixer food_processor grater peeler rolling_pin grill lid foil plastic_wrap".split()
)
# Food types that stand for a recipe's ingredients, the most widely placeable first.
FOODS = ("Potato", "Apple", "Tomato", "Egg", "Lettuce", "Bread")
# When those run out, small things the agent can carry stand for ingredients: the order of a plan's steps is
# still checked (picked up before put), their cooking only partly (they get hot, never sliced).
PORTABLES = ("SaltShaker", "PepperShaker", "Bottle", "WineBottle", "DishSponge", "PaperTowelRoll", "SoapBottle")
# What a mixture things are put into stands for.
CONTAINERS = ("Bowl", "Pot", "Pan", "Plate", "Cup", "Mug")
INTO = ("put", "pour")  # primitives whose second argument is where the first goes


@dataclass(frozen=True)
class Casting:
    """Where a plan runs: the scene, the objectIds bound to names beforehand, or why it cannot run."""

    scene: str
    bound: Mapping[str, str]
    missing: tuple[str, ...] = ()  # names nothing can stand for
    hidden: int = 0  # stand-ins that start shut away in a cabinet or fridge: a worse kitchen for the plan


def plan_names(plan: Iterable[Call]) -> tuple[str, ...]:
    """The object names a plan uses, in order (a wait's subject, but not its state or a timer)."""
    names: dict[str, None] = {}
    for call in plan:
        args = call.args[:1] if call.is_wait else call.args
        names.update((a, None) for a in args if a != TIMER)
    return tuple(names)


def build_frame(plan: tuple[Call, ...], liquids: frozenset[str]) -> Casting:
    """The best kitchen for the plan and the stand-ins bound in it."""
    names = [n for n in plan_names(plan) if n not in liquids]
    missing = tuple(n for n in names if n in NO_COUNTERPART)
    if missing:
        return Casting("", {}, missing)
    return best_frame(names, {call.args[1] for call in plan if call.name in INTO and len(call.args) == 2})


def best_frame(names: Iterable[str], into: Collection[str], asks: Mapping[str, Collection[str]] = {}) -> Casting:
    """The kitchen where most of `names` find an object or a stand-in (`into`: the names things go into;
    `asks`: the states a name must be able to take, `cooked`, `sliced`), and the stand-ins bound in it; a name
    of `NO_COUNTERPART` stays missing."""
    names = [n for n in dict.fromkeys(names) if n not in NO_COUNTERPART]
    frames = [frame_in(scene, names, into, asks) for scene in scene_names()]
    return min(frames, key=lambda f: (len(f.missing), f.hidden, _number(f.scene)))


def frame_in(scene: str, names: list[str], into: Collection[str], asks: Mapping[str, Collection[str]] = {}
             ) -> Casting:
    objects = _objects(scene)
    available = {object_type for object_type, _ in objects}
    left = Counter(object_type for object_type, _ in objects)  # objects of each type no name has yet
    direct = []  # names bound to an object of their own type later (by the kitchen, or the world model)
    for name in names:
        free = next((t for t in types_for(name, available) if left[t]), None)
        if free is not None:
            left[free] -= 1
            direct.append(name)
    named_types = {t for n in direct for t in types_for(n, available)}
    able = _able(scene)  # the chicken to be fried is a Potato rather than an Apple, while one is left
    bound: dict[str, str] = {}
    missing: list[str] = []
    for name in names:
        if name in direct:
            continue
        own = types_for(name, _all_types())
        if own and not types_for(name, available):
            wanted: tuple[str, ...] = ()  # a THOR object other kitchens have: missing here
        else:  # an ingredient or a mixture; or one more bowl than the kitchen has: a container of another type
            kinds = CONTAINERS if name in into or set(own) & set(CONTAINERS) else FOODS + PORTABLES
            wanted = (STAND_INS.get(name) or STAND_INS.get(name.rsplit("_", 1)[-1])  # a medium_saucepan is a saucepan
                      or tuple(sorted((t for t in kinds if t not in named_types),
                                      key=lambda t: len(set(asks.get(name, ())) - able.get(t, set())))))
        chosen = _first_free(objects, wanted, left, set(bound.values()))
        if chosen is None:
            missing.append(name)
        else:
            bound[name] = chosen
    hidden = sum(1 for object_id in bound.values() if object_id in _shut_away(scene))
    return Casting(scene, bound, tuple(missing), hidden)


def _first_free(objects: tuple[tuple[str, str], ...], wanted: tuple[str, ...], left: Counter[str],
                taken: set[str]) -> str | None:
    for object_type in wanted:
        for kind, object_id in objects:
            if kind == object_type and left[kind] and object_id not in taken:
                left[kind] -= 1
                return object_id
    return None


@cache
def _objects(scene: str) -> tuple[tuple[str, str], ...]:
    """(type, objectId) of every object of a kitchen at its start, those in plain sight first (a stand-in
    shut in a cabinet would fail a plan that never mentions the cabinet)."""
    things = sorted(scene_objects(scene), key=lambda o: o["objectId"] in _shut_away(scene))
    return tuple((o["objectType"], o["objectId"]) for o in things)


@cache
def _able(scene: str) -> dict[str, set[str]]:
    """Which of the states a recipe asks (sliced, cooked) each object type of the kitchen can take: cooked
    also when its slices can be (bread)."""
    slicing = load_type_rules().slicing
    able: dict[str, set[str]] = {}
    for thing in scene_objects(scene):
        rule = slicing.get(thing["objectType"])
        states = {"sliced"} if thing.get("sliceable") else set()
        states |= {"cooked"} if thing.get("cookable") or (rule and rule.cookable) else set()
        able.setdefault(thing["objectType"], set()).update(states)
    return able


@cache
def _shut_away(scene: str) -> frozenset[str]:
    return frozenset(shut_away(scene_objects(scene)))


@cache
def _all_types() -> frozenset[str]:
    return frozenset(object_type for scene in scene_names() for object_type, _ in _objects(scene))


def _number(scene: str) -> int:
    return int(scene.removeprefix("FloorPlan"))
