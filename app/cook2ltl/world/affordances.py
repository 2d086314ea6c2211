"""The plan lines that can be applied in a state: what state-aware decoding lets the model write next.

Only primitives, over the objects the prompt names, each line checked in the world (Grounded Decoding,
Huang et al. 2023; SayCan's affordances): picking up an oven, putting before picking up or cutting with no
knife in hand are never offered. A wait is offered for a state time would bring about, a timer only when
time would change something.
"""

from __future__ import annotations

from collections.abc import Iterable

from cook2ltl.domain.actions import CONDITION, TIMER, Call, PrimitiveSet
from cook2ltl.world.logic import State, bindings, holds
from cook2ltl.world.world import World


def admissible_calls(world: World, state: State, primitives: PrimitiveSet, objects: Iterable[str],
                     states: Iterable[str], durations: Iterable[str]) -> list[Call]:
    present = set(state.objects)
    names = tuple(o for o in dict.fromkeys(objects) if o in present)
    # Bindings are drawn from the facts too: only those about named objects, or a line could name any object.
    kept = set(names)
    named = State(names, frozenset(f for f in state.facts if all(a in kept for a in f[1:])))
    calls: list[Call] = []
    for primitive in primitives.primitives:
        if primitive.params == (CONDITION,):
            calls.extend(_waits(world, state, primitive.name, named.objects, states, durations))
            continue
        schema = world.domain.schemas.get(primitive.name)
        if schema is None or len(schema.parameters) != len(primitive.params):
            continue
        for env in bindings(schema.parameters, schema.precondition, named, {}):
            if holds(schema.precondition, state, env):
                calls.append(Call(primitive.name, tuple(env[p] for p in schema.parameters)))
    return calls


def _waits(world: World, state: State, name: str, objects: tuple[str, ...], states: Iterable[str],
           durations: Iterable[str]) -> list[Call]:
    after = world.passed(state)
    if after.facts == state.facts:
        return []
    waits = []
    for word in dict.fromkeys(states):
        predicate = world.predicate(word)
        if predicate is None:
            continue
        waits.extend(Call(name, (o, word)) for o in objects
                     if (predicate, o) in after.facts and (predicate, o) not in state.facts)
    waits.extend(Call(name, (TIMER, d)) for d in dict.fromkeys(durations))
    return waits
