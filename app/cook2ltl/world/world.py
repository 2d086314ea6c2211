"""A primitive set's world: its PDDL domain, the words its plans use for states, and plan lines applied to states.

A plan line is a `Call` of the primitive set; it is the domain action of the same name with the same objects,
but for `wait(x == s)`: time passes — every process of the domain (an action named `process-…`) whose
condition holds acts at once — after which x must be in state s. The
words a set uses for states (`golden`, `boiling`) name domain predicates through its `[world.states]` table; a
word that names none is a state the world cannot observe, and waiting for it is waiting for time.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from cook2ltl.domain.actions import TIMER, Call
from cook2ltl.world.explain import why_not
from cook2ltl.world.logic import (
    Fact, State, applicable, bindings, effects_of, ground, holds, match_atom, positive_facts, successor,
)
from cook2ltl.world.pddl import Domain

PROCESS = "process-"
KEPT = ("enclosed", "carried")  # facts the domains keep up to date from the others (see kept_facts)


@dataclass(frozen=True)
class Applied:
    """One line applied: the state after it, or why it cannot be applied (the state is then unchanged)."""

    state: State
    problem: str = ""

    @property
    def applied(self) -> bool:
        return not self.problem


@dataclass(frozen=True)
class World:
    domain: Domain
    states: Mapping[str, str] = field(default_factory=dict)  # a state word → the predicate it names
    liquid_fill: str | None = None  # fill(container, liquid): how the world tells where a liquid is (THOR)

    def predicate(self, word: str) -> str | None:
        """The unary predicate a state word names in this world, or None if the world cannot observe it."""
        name = self.states.get(word, word)
        return name if self.domain.predicates.get(name) == 1 else None

    def condition(self, call: Call) -> Fact | None:
        """What a wait line waits for, as a fact; None for a timer or a state the world cannot observe."""
        subject, word = call.args
        predicate = None if subject == TIMER else self.predicate(word)
        return (predicate, subject) if predicate else None

    def apply(self, state: State, call: Call) -> Applied:
        if call.is_wait:
            return self._wait(state, call)
        schema = self.domain.schemas.get(call.name)
        if schema is None:
            return Applied(state, f"{call.name} is not an action of the world model {self.domain.name!r}")
        missing = [arg for arg in call.args if arg not in state.objects]
        if missing:
            return Applied(state, f"there is no {', '.join(missing)} in the kitchen")
        if not applicable(schema, call.args, state):
            return Applied(state, self.refusal(schema.name, call, state))
        return Applied(successor(schema, call.args, state))

    def passed(self, state: State) -> State:
        """The state after time passes: every applicable process acts, all read in the same state."""
        added: set[Fact] = set()
        deleted: set[Fact] = set()
        for schema in self.domain.schemas.values():
            if not schema.name.startswith(PROCESS):
                continue
            for env in bindings(schema.parameters, schema.precondition, state, {}):
                if holds(schema.precondition, state, env):
                    more, fewer = effects_of(schema, env, state)
                    added |= more
                    deleted |= fewer
        return state.changed(deleted - added, added)

    def _wait(self, state: State, call: Call) -> Applied:
        after = self.passed(state)
        goal = self.condition(call) if len(call.args) == 2 else None
        if goal is not None and goal not in after.facts:
            return Applied(state, f"{call.args[0]} never becomes {call.args[1]} here: nothing makes it {goal[0]}")
        return Applied(after)

    def possible(self, state: State, fact: Fact) -> bool:
        """Whether an action or process of the domain could ever make `fact` true, as far as the kinds of
        things in `state` tell (the facts no action makes true): `in(mix, ribs)` cannot when ribs holds
        nothing. Only a fact that surely cannot is refused."""
        if fact in state.facts:
            return True
        for schema in self.domain.schemas.values():
            for effect in schema.effects:
                if not effect.value or effect.fact.predicate != fact[0]:
                    continue
                env = match_atom(effect.fact, fact, {})
                if env is None:
                    continue
                needs = (*positive_facts(schema.precondition), *positive_facts(effect.condition))
                if all(ground(a, env) in state.facts for a in needs if self._settled_by(a, env)):
                    return True
        return False

    def _settled_by(self, atom, env: dict) -> bool:
        """Whether `atom` is a kind no action adds (so only the state can make it hold), fully bound by `env`."""
        return atom.predicate in self.domain.never_added and all(not t.startswith("?") or t in env for t in atom.args)

    def refusal(self, name: str, call: Call, state: State) -> str:
        return why_not(self.domain.schemas[name], call.args, state)


def kept_facts(facts: set[Fact] | frozenset[Fact]) -> set[Fact]:
    """The facts the domains keep up to date instead of asking a negated quantifier, for a kitchen's start:
    `enclosed` (shut inside a closed container, or inside something inside one) and `carried` (inside the
    held object, or inside something inside it)."""
    closed = {f[1] for f in facts if f[0] == "openable"} - {f[1] for f in facts if f[0] == "opened"}
    held = {f[1] for f in facts if f[0] == "holding"}
    parent = {f[1]: f[2] for f in facts if f[0] == "in"}
    kept = {("enclosed", x) for x, c in parent.items() if c in closed or parent.get(c) in closed}
    return kept | {("carried", x) for x, c in parent.items() if c in held or parent.get(c) in held}
