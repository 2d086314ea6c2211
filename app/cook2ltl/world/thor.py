"""The ai2thor world's state (assets/domains/ai2thor.pddl) read off THOR event metadata.

`thor_state(event.metadata["objects"], names, rules)` binds each name of a plan to one THOR object, the
way a cook would pick among several: a thing not shut away (one in hand first), a container holding
another named thing (the knife's drawer), the knob of the chosen burner, the faucet nearest the chosen
sink. Two names never share an object (`sink` is the Sink when `sink_basin` has the basin); a name left
with no object of its own is left out. The executor runs plans on the same binding:
`execute(kitchen, atom, Binding(objects=binding))`.

The state's objects are the bound names, the liquids, and what the rules need besides: every container
of a named thing (so `in` is always the direct container and a closed cabinet shuts its contents away),
the knob of every burner, the faucet of every sink basin, the thing in hand. These get made-up names
(`cabinet_2`) and are bound like the rest. A name stands for its object or, once cut, for its pieces:
a predicate holds of it when it holds of any piece, as the rollout reads facts (kitchen.facts).

Only metadata is read, so a real THOR build's events work too. The embedded kitchen settles after every
action and every scene loads settled, so what it reports is a state the domain's actions start from.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence

from cook2ltl.kitchen.facts import PREDICATES
from cook2ltl.kitchen.names import Binding, Obj, key, known_types, objects_named, piece_types, shut_away, snake_case
from cook2ltl.kitchen.names import types_for
from cook2ltl.kitchen.state import TypeRules
from cook2ltl.world.logic import Fact, State

# THOR's ability flags → the domain's kind predicates
FLAGS = {
    "pickupable": "pickupable", "receptacle": "receptacle", "openable": "openable", "toggleable": "toggleable",
    "sliceable": "sliceable", "cookable": "cookable", "canFillWithLiquid": "fillable", "dirtyable": "dirtyable",
    "breakable": "breakable", "canBeUsedUp": "usable", "isHeatSource": "heat-source", "isColdSource": "cold-source",
}
# kitchen.facts' readings → the domain's state predicates
STATES = {word: word for word in ("hot", "cold", "room_temperature", "cooked", "sliced", "broken", "filled",
                                  "used_up", "dirty", "on")} | {"open": "opened"}
DEPENDENT = {"StoveKnob", "Faucet"}  # chosen after what they serve
BREWER, FLOOR, BASIN = "CoffeeMachine", "Floor", "SinkBasin"
BREW, TAP = "coffee", "water"  # what a coffee machine and a faucet fill a cup with


def thor_state(objects: Sequence[Mapping], names: Iterable[str], rules: TypeRules,
               bound: Mapping[str, str] = {}) -> tuple[State, dict[str, str]]:
    """The world state of the kitchen whose metadata objects are `objects`, over `names` (bound as
    `bound` says where it says so), and the objectId each of its objects stands for."""
    scene = _Scene(objects)
    given = [n for n in dict.fromkeys(names) if n not in rules.liquids]
    binding = {n: i for n, i in bound.items() if n not in rules.liquids}
    _choose(scene, [n for n in given if n not in binding], binding)
    _add_extras(scene, given, binding)
    liquids = sorted(rules.liquids)
    facts = _facts(scene, binding, liquids, rules)
    return State((*binding, *liquids), frozenset(facts)), binding


class _Scene:
    """The metadata, indexed: each object's direct container, each sink's nearest faucet."""

    def __init__(self, objects: Sequence[Mapping]) -> None:
        self.objects = list(objects)
        self.by_id = {o["objectId"]: o for o in self.objects}
        self.parent = {oid: _direct_parent(o, self.by_id) for oid, o in self.by_id.items()}
        self.shut = shut_away(self.objects)
        self.available = known_types(self.objects)
        faucets = [o for o in self.objects if o["objectType"] == "Faucet"]
        # as the kitchen's settle does: a basin's faucet is the nearest one, first in scene order on a tie
        self.faucet_of = {o["objectId"]: min(faucets, key=lambda f: _distance(f, o))["objectId"]
                          for o in self.objects if o["objectType"] in (BASIN, "Sink") and faucets}

    def ancestors(self, oid: str) -> list[str]:
        chain, node = [], self.parent.get(oid)
        while node is not None and node not in chain and node != oid:
            chain.append(node)
            node = self.parent.get(node)
        return chain


def _direct_parent(o: Mapping, by_id: Mapping[str, Mapping]) -> str | None:
    """The innermost of `parentReceptacles`: the embedded kitchen lists the chain nearest first, a real
    THOR build every receptacle touched; the innermost is the one no other of them sits in."""
    parents = [p for p in o.get("parentReceptacles") or () if p in by_id]
    for p in parents:
        if not any(p in (by_id[q].get("parentReceptacles") or ()) for q in parents if q != p):
            return p
    return parents[0] if parents else None


def _distance(a: Mapping, b: Mapping) -> float:
    pa, pb = a["position"], b["position"]
    return math.dist((pa["x"], pa["y"], pa["z"]), (pb["x"], pb["y"], pb["z"]))


def _whole(o: Mapping) -> str:
    """The id a name is bound to: a piece's (`Tomato|…|TomatoSliced_0`) is the cut object's."""
    head, _, tail = o["objectId"].rpartition("|")
    return head if head and tail.startswith(o["objectType"] + "_") else o["objectId"]


def _choose(scene: _Scene, names: list[str], binding: dict[str, str]) -> None:
    """Bind each name: things first, then fixtures (which then prefer holding a named thing), then knobs
    and faucets (which prefer serving a named burner or sink); a name that is its type's own word
    (sink_basin) chooses before one standing in for it (sink)."""

    def role(name: str) -> int:
        types = types_for(name, scene.available)
        if types and set(types) <= DEPENDENT:
            return 2
        return 0 if any(o.get("pickupable") for o in objects_named(name, scene.objects, Binding())) else 1

    def exact(name: str) -> bool:
        types = types_for(name, scene.available)
        return bool(types) and key(types[0]) == key(name)

    own = {n: types_for(n, scene.available)[0] for n in names if exact(n)}
    for name in sorted(names, key=lambda n: (role(n), not exact(n), names.index(n))):
        taken = set(binding.values())
        candidates = [o for o in objects_named(name, scene.objects, Binding()) if not _clashes(_whole(o), taken)]
        # `knife` takes a Knife, not the ButterKnife that `butter_knife` is the word for, while it can
        others = {t for n, t in own.items() if n != name}
        candidates = [o for o in candidates if o["objectType"] not in others] or candidates
        if not candidates:
            continue  # every object of it belongs to another name
        named = [o["objectId"] for o in scene.objects if _whole(o) in taken]
        types = types_for(name, scene.available)
        portable = role(name) == 0

        def rank(o: Obj) -> tuple:
            oid = o["objectId"]
            holds = sum(oid in scene.ancestors(n) for n in named)
            shut = oid in scene.shut
            kind = types.index(o["objectType"]) if o["objectType"] in types else len(types)
            return (not o.get("isPickedUp"), not _related(scene, o, named), portable and shut, -holds, shut, kind,
                    o.get("distance", 0.0), oid)

        binding[name] = _whole(min(candidates, key=rank))


def _clashes(oid: str, taken: set[str]) -> bool:
    """Whether `oid` is taken, or a name bound to it would also stand for a taken object (or the other way
    round): the executor takes `Sink|…` to stand for `Sink|…|SinkBasin` too, as for a cut object's pieces."""
    return any(oid == t or t.startswith(oid + "|") or oid.startswith(t + "|") for t in taken)


def _related(scene: _Scene, o: Obj, named: list[str]) -> bool:
    """Whether `o` switches or is switched by a named object, or is the faucet of a named sink or the
    sink of a named faucet."""
    oid = o["objectId"]
    if set(o.get("controlledObjects") or ()) & set(named):
        return True
    if any(oid in (scene.by_id[n].get("controlledObjects") or ()) for n in named):
        return True
    return any(scene.faucet_of.get(n) == oid for n in named) or scene.faucet_of.get(oid) in named


def _add_extras(scene: _Scene, given: list[str], binding: dict[str, str]) -> None:
    """Add under made-up names what the rules need of the kitchen beyond the named things."""
    ids = {o["objectId"] for o in scene.objects if _whole(o) in set(binding.values())}
    held = [o["objectId"] for o in scene.objects if o.get("isPickedUp")]
    work = sorted(ids) + held
    while work:
        oid = work.pop()
        o = scene.by_id[oid]
        needed = [*scene.ancestors(oid), scene.faucet_of.get(oid) if o["objectType"] == BASIN else None,
                  *sorted(k["objectId"] for k in scene.objects if oid in (k.get("controlledObjects") or ())),
                  oid if oid in held else None]
        for extra in needed:
            # one that clashes with a bound object (the Sink above its bound basin) cannot have a name
            if extra is not None and not _clashes(_whole(scene.by_id[extra]), set(binding.values())):
                binding[_made_up_name(scene.by_id[extra], scene, given, binding)] = _whole(scene.by_id[extra])
                work.append(extra)


def _made_up_name(o: Obj, scene: _Scene, given: list[str], binding: Mapping[str, str]) -> str:
    """`cabinet_2` for a second cabinet when `cabinet` is a plan's name; `floor` for the floor."""
    base = next((n for n in given if o["objectType"] in types_for(n, scene.available)), snake_case(o["objectType"]))
    if base not in given and base not in binding:
        return base
    n = 2
    while f"{base}_{n}" in binding or f"{base}_{n}" in given:
        n += 1
    return f"{base}_{n}"


def _facts(scene: _Scene, binding: Mapping[str, str], liquids: list[str], rules: TypeRules) -> set[Fact]:
    facts: set[Fact] = {("liquid", l) for l in liquids}
    facts |= {("brew", l) for l in liquids if l == BREW} | {("tap-liquid", l) for l in liquids if l == TAP}
    everyone = Binding(objects=binding)
    stands_for = {name: objects_named(name, scene.objects, everyone) for name in binding}
    name_of = {_whole(o): name for name, objs in stands_for.items() for o in objs}
    floor = next((o["objectId"] for o in scene.objects if o["objectType"] == FLOOR), None)
    pieces = set(piece_types().values())
    kind: dict[str, str] = {}  # name → the object type it now is
    for name, objs in stands_for.items():
        # a real THOR build keeps a cut object beside its pieces (isSliced): the pieces are what is there
        live = [o for o in objs if not o.get("isSliced")] or objs
        if not live:
            continue
        kind[name] = live[0]["objectType"]
        facts |= {(predicate, name) for flag, predicate in FLAGS.items() if any(o.get(flag) for o in live)}
        facts |= {(predicate, name) for word, predicate in STATES.items() if any(PREDICATES[word](o) for o in objs)}
        facts |= {("filled-with", name, o["fillLiquid"]) for o in live
                  if o.get("isFilledWithLiquid") and o.get("fillLiquid") in liquids}
        facts |= {("holding", name) for o in live if o.get("isPickedUp")}
        facts |= {("in", name, name_of[_whole(scene.by_id[p])]) for o in live
                  if (p := scene.parent.get(o["objectId"])) is not None and _whole(scene.by_id[p]) in name_of}
        rule = rules.slicing.get(kind[name])
        facts |= {(k, name) for k, holds in (("cutter", kind[name] in rules.cutting_tools), ("splits", rule),
                                             ("pieces-cookable", rule and rule.cookable),
                                             ("brewer", kind[name] == BREWER),
                                             ("floor", any(o["objectId"] == floor for o in live))) if holds}
        for o in live:
            facts |= {("controls", name, name_of[c]) for c in o.get("controlledObjects") or () if c in name_of}
            if o["objectType"] == BASIN and scene.faucet_of.get(o["objectId"]) in name_of:
                facts.add(("rinses", name_of[scene.faucet_of[o["objectId"]]], name))
    if not any(o.get("isPickedUp") for o in scene.objects):
        facts.add(("hand-empty",))
    for x, x_type in kind.items():
        # the pieces' type fits where pieces fit; pieces cut again stay as they are
        cut = rules.slicing[x_type].into if x_type in rules.slicing else x_type if x_type in pieces else None
        for r, r_type in kind.items():
            if rules.fits(x_type, r_type):
                facts.add(("fits", x, r))
            if cut is not None and rules.fits(cut, r_type):
                facts.add(("fits-sliced", x, r))
    return facts
