"""A parsed PDDL domain as plain data, and its evaluation on a state: is this action applicable, what follows.

Conditions are small frozen trees (And, Or, Not, Exists, Forall, Fact, Equal, Constant); arguments starting
with `?` are variables. Quantifiers range over the state's objects; a quantifier over a conjunction binds its
variables by joining the positive facts of the conjunction against the state (a tiny query planner), so
`(exists (?c) (and (in ?x ?c) (openable ?c)))` looks at the containers of ?x only, not at every object.
Effects follow PDDL: every condition is read in the old state, deletes are applied before adds.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import Union

Fact = tuple[str, ...]  # ("in", "egg", "pot"): a predicate and its objects
# A condition made into a function once (each node's `test`, cached on it): holds(condition, state, env) is
# condition.test(state, env), with no dispatch on the node's type at every evaluation.
Test = Callable[["State", Mapping[str, str]], bool]


@dataclass(frozen=True)
class State:
    """The objects of a world and the facts true of them (static kinds included)."""

    objects: tuple[str, ...]
    facts: frozenset[Fact]

    @cached_property
    def by_predicate(self) -> Mapping[str, tuple[Fact, ...]]:
        index: dict[str, list[Fact]] = {}
        for fact in self.facts:
            index.setdefault(fact[0], []).append(fact)
        return {name: tuple(facts) for name, facts in index.items()}

    def holds(self, *fact: str) -> bool:
        return tuple(fact) in self.facts

    def changed(self, deleted: set[Fact], added: set[Fact]) -> State:
        return State(self.objects, (self.facts - deleted) | added)


@dataclass(frozen=True)
class Atom:
    predicate: str
    args: tuple[str, ...]

    @cached_property
    def free(self) -> frozenset[str]:
        return frozenset(a for a in self.args if a.startswith("?"))

    @cached_property
    def test(self) -> Test:
        predicate, args = self.predicate, self.args
        if not any(a.startswith("?") for a in args):
            fact = (predicate, *args)
            return lambda state, env: fact in state.facts
        return lambda state, env: (predicate, *(env[a] if a.startswith("?") else a for a in args)) in state.facts


@dataclass(frozen=True)
class Equal:
    left: str
    right: str

    @cached_property
    def free(self) -> frozenset[str]:
        return frozenset(t for t in (self.left, self.right) if t.startswith("?"))

    @cached_property
    def test(self) -> Test:
        left, right = self.left, self.right
        return lambda state, env: value_of(left, env) == value_of(right, env)


@dataclass(frozen=True)
class Constant:
    value: bool

    free = frozenset()

    @cached_property
    def test(self) -> Test:
        value = self.value
        return lambda state, env: value


@dataclass(frozen=True)
class Not:
    arg: Condition

    @cached_property
    def free(self) -> frozenset[str]:
        return self.arg.free

    @cached_property
    def test(self) -> Test:
        arg = self.arg.test
        return lambda state, env: not arg(state, env)


@dataclass(frozen=True)
class _Junction:
    args: tuple[Condition, ...]

    @cached_property
    def free(self) -> frozenset[str]:
        return frozenset().union(*(a.free for a in self.args))


@dataclass(frozen=True)
class And(_Junction):
    @cached_property
    def test(self) -> Test:
        tests = tuple(a.test for a in self.args)
        return lambda state, env: all(t(state, env) for t in tests)


@dataclass(frozen=True)
class Or(_Junction):
    @cached_property
    def test(self) -> Test:
        tests = tuple(a.test for a in self.args)
        return lambda state, env: any(t(state, env) for t in tests)


@dataclass(frozen=True)
class _Quantified:
    variables: tuple[str, ...]
    body: Condition

    @cached_property
    def free(self) -> frozenset[str]:
        return self.body.free - set(self.variables)


@dataclass(frozen=True)
class Exists(_Quantified):
    @cached_property
    def test(self) -> Test:
        variables, test = list(self.variables), self.body.test
        facts, checks = positive_facts(self.body), _checks(self.body)  # planned once: this runs in hot loops
        return lambda state, env: any(test(state, e) for e in _join(variables, facts, checks, state, dict(env)))


@dataclass(frozen=True)
class Forall(_Quantified):
    @cached_property
    def test(self) -> Test:
        variables, test = list(self.variables), self.body.test
        return lambda state, env: all(test(state, e) for e in _join(variables, [], [], state, dict(env)))


Condition = Union[Atom, Equal, Constant, Not, And, Or, Exists, Forall]
Env = Mapping[str, str]


@dataclass(frozen=True)
class Effect:
    """`forall variables: when condition: fact := value`."""

    fact: Atom
    value: bool
    condition: Condition = Constant(True)
    variables: tuple[str, ...] = ()


@dataclass(frozen=True)
class Schema:
    """One action of the domain."""

    name: str
    parameters: tuple[str, ...]  # variable names, `?x`
    precondition: Condition
    effects: tuple[Effect, ...] = field(default=())


def value_of(term: str, env: Env) -> str:
    return env[term] if term.startswith("?") else term


def ground(atom: Atom, env: Env) -> Fact:
    return (atom.predicate, *(value_of(a, env) for a in atom.args))


def holds(condition: Condition, state: State, env: Env) -> bool:
    return condition.test(state, env)


def bindings(variables: tuple[str, ...], condition: Condition, state: State, env: Env) -> Iterator[dict[str, str]]:
    """Values of `variables` (extending `env`) that may satisfy `condition`: every binding that does is
    among them. Positive facts of a conjunction narrow the search; the rest range over all objects, and a
    conjunct is tested as soon as its variables are bound, so a binding that fails it is not extended."""
    yield from _join(list(variables), positive_facts(condition), _checks(condition), state, dict(env))


def _checks(condition: Condition) -> list[tuple[frozenset[str], Test]]:
    return [(c.free, c.test) for c in conjuncts(condition)]


def positive_facts(condition: Condition) -> list[Atom]:
    """The atoms a condition asserts outright: itself, or those of a conjunction, however nested."""
    return [c for c in conjuncts(condition) if isinstance(c, Atom)]


def conjuncts(condition: Condition) -> list[Condition]:
    """What must each hold for `condition` to hold: itself, or the parts of a conjunction, however nested."""
    if isinstance(condition, And):
        return [c for arg in condition.args for c in conjuncts(arg)]
    return [condition]


def _join(free: list[str], facts: list[Atom], checks: list[tuple[frozenset[str], Test]], state: State,
          env: dict[str, str]) -> Iterator[dict[str, str]]:
    pending = []
    for names, test in checks:
        if not names <= env.keys():
            pending.append((names, test))
        elif not test(state, env):
            return  # no extension of this binding can satisfy the condition
    unbound = [v for v in free if v not in env]
    if not unbound:
        yield env
        return
    atom = next((a for a in facts if any(arg in unbound for arg in a.args)), None)
    if atom is None:
        variable = unbound[0]
        for obj in state.objects:
            yield from _join(free, facts, pending, state, {**env, variable: obj})
        return
    rest = [a for a in facts if a is not atom]
    for fact in state.by_predicate.get(atom.predicate, ()):
        extended = match_atom(atom, fact, env)
        if extended is not None:
            yield from _join(free, rest, pending, state, extended)


def match_atom(atom: Atom, fact: Fact, env: Env) -> dict[str, str] | None:
    """`env` extended so that `atom` grounds to `fact`, or None if it cannot."""
    if len(fact) != len(atom.args) + 1:
        return None
    extended = dict(env)
    for term, value in zip(atom.args, fact[1:]):
        if term.startswith("?"):
            if extended.setdefault(term, value) != value:
                return None
        elif term != value:
            return None
    return extended


def applicable(schema: Schema, args: tuple[str, ...], state: State) -> bool:
    if len(args) != len(schema.parameters) or any(a not in state.objects for a in args):
        return False
    return holds(schema.precondition, state, dict(zip(schema.parameters, args)))


def successor(schema: Schema, args: tuple[str, ...], state: State) -> State:
    """The state after the action (its precondition is the caller's to check)."""
    added, deleted = effects_of(schema, dict(zip(schema.parameters, args)), state)
    return state.changed(deleted, added)


def effects_of(schema: Schema, env: Env, state: State) -> tuple[set[Fact], set[Fact]]:
    """(facts added, facts deleted) by the action with parameters `env`, every condition read in `state`."""
    added: set[Fact] = set()
    deleted: set[Fact] = set()
    for effect in schema.effects:
        for binding in bindings(effect.variables, effect.condition, state, env):
            if holds(effect.condition, state, binding):
                (added if effect.value else deleted).add(ground(effect.fact, binding))
    return added, deleted
