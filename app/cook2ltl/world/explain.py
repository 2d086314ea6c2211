"""Why a plan line cannot be applied, in words a cook (and a model shown its failed plan) can read.

The first failing part of the action's precondition is named: `pick_up(oven)`: "oven cannot be picked
up"; `put(egg, pot)`: "not holding egg". Predicates without a phrase are shown as PDDL.
"""

from __future__ import annotations

from cook2ltl.world.logic import And, Atom, Condition, Env, Exists, Not, Or, Schema, State, ground, holds

# predicate → (phrase when it is needed but false, phrase when it must be false but holds)
PHRASES = {
    "holding": ("not holding {0}", "{0} is in hand"),
    "hand-empty": ("the hand is full", "the hand is empty"),
    "portable": ("{0} cannot be picked up", ""),
    "pickupable": ("{0} cannot be picked up", ""),
    "receptacle": ("nothing can be put in or on {0}", ""),
    "openable": ("{0} cannot be opened or closed", ""),
    "opened": ("{0} is closed", "{0} is open"),
    "switchable": ("{0} is not something to switch on or off", ""),
    "toggleable": ("{0} is not something to switch on or off", ""),
    "on": ("{0} is off", "{0} is on"),
    "in": ("{0} is not in {1}", "{1} holds {0}"),
    "food": ("{0} is not food", ""),
    "liquid": ("{0} is not a liquid", "{0} is a liquid"),
    "sliced": ("{0} is not cut", "{0} is already cut"),
    "sliceable": ("{0} cannot be cut", ""),
    "enclosed": ("", "{0} is shut inside something closed; open it first"),
    "carried": ("", "{0} is inside what is in hand; put that down first"),
    "vessel": ("nothing can be poured into {0}", ""),
    "fits": ("{0} does not fit in or on {1}", ""),
}


def why_not(schema: Schema, args: tuple[str, ...], state: State) -> str:
    env = dict(zip(schema.parameters, args))
    failing = _first_failing(schema.precondition, state, env)
    return _phrase(failing, state, env) if failing is not None else "its precondition does not hold"


def _first_failing(condition: Condition, state: State, env: Env) -> Condition | None:
    if isinstance(condition, And):
        for part in condition.args:
            found = _first_failing(part, state, env)
            if found is not None:
                return found
        return None
    return None if holds(condition, state, env) else condition


def _phrase(condition: Condition, state: State, env: Env) -> str:
    if isinstance(condition, Atom):
        return _atom_phrase(ground(condition, env), True)
    if isinstance(condition, Or):  # the first way it could have held is the usual one
        return _phrase(condition.args[0], state, env)
    if isinstance(condition, Not) and isinstance(condition.arg, Atom):
        return _atom_phrase(ground(condition.arg, env), False)
    if isinstance(condition, Exists) and isinstance(condition.body, And):
        wanted = [a for a in condition.body.args if isinstance(a, Atom)]
        if any(a.predicate == "holding" for a in wanted):
            kinds = [a.predicate for a in wanted if a.predicate != "holding"]
            return f"nothing in hand is a {' '.join(kinds) or 'tool'} for it"
    return f"needs {_pddl(condition, env)}"


def _atom_phrase(fact: tuple[str, ...], needed: bool) -> str:
    phrases = PHRASES.get(fact[0])
    text = phrases[0 if needed else 1] if phrases else ""
    if text:
        return text.format(*fact[1:])
    call = f"{fact[0]}({', '.join(fact[1:])})" if len(fact) > 1 else fact[0]
    return f"{call} {'is false' if needed else 'holds'}"


def _pddl(condition: Condition, env: Env) -> str:
    text = repr(condition)
    for variable, value in env.items():
        text = text.replace(f"'{variable}'", value)
    return text
