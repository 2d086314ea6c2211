"""The ai2thor world's state (assets/domains/ai2thor.pddl) read off THOR event metadata.

`thor_state(event.metadata["objects"], names, rules)` binds each name of a plan to one THOR object, the
way a cook would pick among several: a thing not shut away (one in hand first), a container holding
another named thing (the knife's drawer), the knob of the chosen burner, the faucet nearest the chosen
sink; a name that is its type's own word comes first (`butter_knife` gets the ButterKnife, `knife` the
Knife). Two names never share an object, and a name left with none of its own is left out: `sink` when
`sink_basin` has the basin (the Sink around it would not do: the executor takes a name bound to
`Sink|…` to stand for `Sink|…|SinkBasin` too). The executor runs plans on the same binding:
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
from collections import Counter
from collections.abc import Collection, Iterable, Mapping, Sequence

from cook2ltl.thor_types import TypeRules
from cook2ltl.world.logic import Fact, State
from cook2ltl.world.thor_facts import PREDICATES
from cook2ltl.world.thor_names import (
    Binding, Obj, key, known_types, objects_named, piece_types, shut_away, snake_case, types_for,
)
from cook2ltl.world.world import kept_facts

# THOR's ability flags → the domain's kind predicates
FLAGS = {
    "pickupable": "pickupable", "receptacle": "receptacle", "openable": "openable", "toggleable": "toggleable",
    "sliceable": "sliceable", "cookable": "cookable", "canFillWithLiquid": "fillable", "dirtyable": "dirtyable",
    "breakable": "breakable", "canBeUsedUp": "usable", "isHeatSource": "heat-source", "isColdSource": "cold-source",
}
# kitchen.facts' readings → the domain's state predicates
STATES = {word: word for word in ("hot", "cold", "room_temperature", "cooked", "sliced", "broken", "filled",
                                  "used_up", "dirty", "clean", "on")} | {"open": "opened"}
DEPENDENT = {"StoveKnob", "Faucet"}  # chosen after what they serve
BREWER, FLOOR, BASIN = "CoffeeMachine", "Floor", "SinkBasin"
BREW, TAP = "coffee", "water"  # what a coffee machine and a faucet fill a cup with


def thor_state(objects: Sequence[Mapping], names: Iterable[str], rules: TypeRules,
               bound: Mapping[str, str] = {}, spare: Collection[str] = ()) -> tuple[State, dict[str, str]]:
    """The world state of the kitchen whose metadata objects are `objects`, over `names` (bound as
    `bound` says where it says so; the `spare` ones, words a plan may use but the recipe does not, only
    after the others), and the objectId each of its objects stands for."""
    scene = _Scene(objects)
    given = [n for n in dict.fromkeys(names) if n not in rules.liquids]
    binding = {n: i for n, i in bound.items() if n not in rules.liquids}
    _choose(scene, [n for n in given if n not in binding], binding, set(spare))
    _add_extras(scene, given, binding)
    liquids = sorted(rules.liquids)
    facts = _facts(scene, binding, liquids, rules)
    return State((*binding, *liquids), frozenset(facts | kept_facts(facts))), binding


class _Scene:
    """The metadata, indexed: each object's direct container, each burner's knobs, each sink's faucet."""

    def __init__(self, objects: Sequence[Mapping]) -> None:
        self.objects = list(objects)
        self.by_id = {o["objectId"]: o for o in self.objects}
        self.parent = {oid: _direct_parent(o, self.by_id) for oid, o in self.by_id.items()}
        self.shut = shut_away(self.objects)
        self.available = known_types(self.objects)
        self.words: dict[str, str] | None = None  # object type → the plan's word for it, when needed
        self.knobs: dict[str, list[str]] = {}  # burner → the knobs that switch it
        for o in self.objects:
            for switched in o.get("controlledObjects") or ():
                self.knobs.setdefault(switched, []).append(o["objectId"])
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


def _choose(scene: _Scene, names: list[str], binding: dict[str, str], spare: set[str]) -> None:
    """Bind each name: things first, then fixtures (which then prefer holding a named thing), then knobs
    and faucets (which prefer serving a named burner or sink); a name that is its type's own word
    (sink_basin) chooses before one standing in for it (sink)."""

    types = {n: types_for(n, scene.available) for n in names}
    unbound = {n: objects_named(n, scene.objects, Binding()) for n in names}
    role = {n: 2 if types[n] and set(types[n]) <= DEPENDENT else 0 if any(o.get("pickupable") for o in unbound[n])
            else 1 for n in names}
    own = {n: types[n][0] for n in names if types[n] and key(types[n][0]) == key(n)}
    for name in sorted(names, key=lambda n: (role[n], n in spare, n not in own, names.index(n))):
        taken = set(binding.values())
        candidates = [o for o in unbound[name] if not _clashes(_whole(o), taken)]
        # `knife` takes a Knife, not the ButterKnife that `butter_knife` is the word for, while it can
        others = {t for n, t in own.items() if n != name}
        candidates = [o for o in candidates if o["objectType"] not in others] or candidates
        if not candidates:
            continue  # every object of it belongs to another name
        named = [o["objectId"] for o in scene.objects if _whole(o) in taken]
        holding = Counter(a for n in named for a in scene.ancestors(n))  # container → named things in it
        portable = role[name] == 0

        def rank(o: Obj, types: tuple[str, ...] = types[name]) -> tuple:
            oid = o["objectId"]
            holds = holding[oid]
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
    taken = set(binding.values())
    held = [o["objectId"] for o in scene.objects if o.get("isPickedUp")]
    work = sorted(o["objectId"] for o in scene.objects if _whole(o) in taken) + held
    while work:
        oid = work.pop()
        needed = [*scene.ancestors(oid), *sorted(scene.knobs.get(oid, ())), oid if oid in held else None,
                  scene.faucet_of.get(oid) if scene.by_id[oid]["objectType"] == BASIN else None]
        for extra in needed:
            # one that clashes with a bound object (the Sink above its bound basin) cannot have a name
            if extra is not None and not _clashes(_whole(scene.by_id[extra]), taken):
                binding[_made_up_name(scene.by_id[extra], scene, given, binding)] = _whole(scene.by_id[extra])
                taken.add(_whole(scene.by_id[extra]))
                work.append(extra)


def _made_up_name(o: Obj, scene: _Scene, given: list[str], binding: Mapping[str, str]) -> str:
    """`cabinet_2` for a second cabinet when `cabinet` is a plan's name; `floor` for the floor."""
    if scene.words is None:  # each type's word among the plan's names, worked out when first needed
        scene.words = {}
        for word in reversed(given):
            scene.words.update((t, word) for t in types_for(word, scene.available))
    base = scene.words.get(o["objectType"], snake_case(o["objectType"]))
    if base not in given and base not in binding:
        return base
    n = 2
    while f"{base}_{n}" in binding or f"{base}_{n}" in given:
        n += 1
    return f"{base}_{n}"


def _stands_for(scene: _Scene, binding: Mapping[str, str]) -> dict[str, list[Obj]]:
    """What each name stands for, as `names.objects_named` has it (the object bound, or an object whose id
    extends the bound one: its pieces), in one pass over the objects."""
    named: dict[str, list[str]] = {}
    for name, oid in binding.items():
        named.setdefault(oid, []).append(name)
    found: dict[str, list[Obj]] = {name: [] for name in binding}
    for o in scene.objects:
        prefix = o["objectId"]
        while prefix:
            for name in named.get(prefix, ()):
                found[name].append(o)
            prefix = prefix.rpartition("|")[0]
    return found


def _facts(scene: _Scene, binding: Mapping[str, str], liquids: list[str], rules: TypeRules) -> set[Fact]:
    facts: set[Fact] = {("liquid", liquid) for liquid in liquids}
    facts |= {("brew", BREW)} & {("brew", liquid) for liquid in liquids}
    facts |= {("tap-liquid", TAP)} & {("tap-liquid", liquid) for liquid in liquids}
    stands_for = _stands_for(scene, binding)
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
    by_type: dict[str, list[str]] = {}
    for name, object_type in kind.items():
        by_type.setdefault(object_type, []).append(name)
    for x_type, xs in by_type.items():
        # the pieces' type fits where pieces fit; pieces cut again stay as they are
        cut = rules.slicing[x_type].into if x_type in rules.slicing else x_type if x_type in pieces else None
        for predicate, of in (("fits", x_type), ("fits-sliced", cut)):
            for r_type in rules.receptacles.get(of, ()) if of is not None else ():
                facts |= {(predicate, x, r) for x in xs for r in by_type.get(r_type, ())}
    return facts
