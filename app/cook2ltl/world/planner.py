"""Classical planning from a state to a goal: unified-planning's OneshotPlanner with Fast Downward behind it.

`Planner` is the small interface the checks need; `FastDownward` builds unified-planning's own Problem from
the domain file (read once), the state's objects and facts and the goal, and solves it. Its plan comes back as
calls of the primitive set: the domain's `wait` is written as a wait for the first state it brings about
that the goal asks for (else any it brings about), as `wait(pasta == cooked)`.
"""

from __future__ import annotations

import threading
from collections.abc import Iterable, Mapping, Sequence
from functools import cache
from pathlib import Path
from typing import Protocol

from cook2ltl.domain.actions import WAIT, Call
from cook2ltl.world.logic import Fact, State, effects_of
from cook2ltl.world.pddl import read_with_unified_planning
from cook2ltl.world.world import PROCESS, World

ENGINE = "fast-downward"
# The translator's invariant synthesis only speeds the search up; on the THOR domain's conditional effects it
# can take minutes, so it gets a second.
ENGINE_OPTIONS = {"fast_downward_translate_options": ["--invariant-generation-max-time", "1"]}
INSIDE = "in"
HOLDING = "holding"
TIME_LIMIT = 20.0  # seconds for one search; the kitchens' problems take well under one
# unified-planning's expressions live in one environment per process, which is not safe to build in from two
# threads at once: every search, by any planner, takes this lock.
_SEARCHING = threading.Lock()


class Planner(Protocol):
    def plan(self, world: World, state: State, goal: Sequence[Fact]) -> tuple[Call, ...] | None:
        """Calls that take `state` to one where every goal fact holds; None when there are none."""

    def kit_for(self, goal: Sequence[Fact]) -> frozenset[str] | None:
        """The everyday things a search for `goal` may use besides the goal's objects; None: every object."""


class FastDownward:
    """Fast Downward through unified-planning; safe to share between threads (one search at a time).

    The search sees only the objects that matter: the goal's, what holds them, what is in hand, and the
    `kit` (a kitchen's everyday pot, knife, stovetop …; None: every object). Grounding every pair of a
    fifty-object kitchen costs Fast Downward minutes, this few seconds."""

    def __init__(self, kit: Iterable[str] | Mapping[str, Iterable[str]] | None = None,
                 time_limit: float = TIME_LIMIT) -> None:
        # a list is used for every goal; a table by goal predicate ("*": every goal) gives what each state needs
        table = {"*": kit} if kit is not None and not isinstance(kit, Mapping) else (kit or {})
        self.kit = None if kit is None else {predicate: frozenset(names) for predicate, names in table.items()}
        self.time_limit = time_limit
        self._solved: dict[tuple, list | None] = {}  # searches done, by their problem up to the names of things

    def plan(self, world: World, state: State, goal: Sequence[Fact]) -> tuple[Call, ...] | None:
        if all_reached(state, goal):
            return ()
        kit = self.kit_for(goal)
        focused = focus(state, goal, kit)
        key, named = _up_to_names(world.domain.path, focused, goal, kit or frozenset())
        with _SEARCHING:
            if key not in self._solved:
                solved = _solve(world.domain.path, focused, tuple(goal), self.time_limit)
                self._solved[key] = _renamed(solved, {real: alias for alias, real in named.items()})
            actions = _renamed(self._solved[key], named)
        return None if actions is None else as_calls(world, state, goal, actions)

    def kit_for(self, goal: Sequence[Fact]) -> frozenset[str] | None:
        return None if self.kit is None else frozenset().union(
            self.kit.get("*", ()), *(self.kit.get(fact[0], ()) for fact in goal))


def all_reached(state: State, goal: Sequence[Fact]) -> bool:
    return all(reached(state, fact) for fact in goal)


def reached(state: State, fact: Fact) -> bool:
    """Whether a goal fact holds; `in(x, y)` also when x is in something in y."""
    if fact in state.facts:
        return True
    if fact[0] != INSIDE:
        return False
    _, x, y = fact
    return any(f[1] == x and (INSIDE, f[2], y) in state.facts for f in state.by_predicate.get(INSIDE, ()))


def focus(state: State, goal: Sequence[Fact], kit: frozenset[str] | None) -> State:
    """`state` narrowed to the goal's objects, the kit, what is held and everything that contains them."""
    if kit is None:
        return state
    keep = {arg for fact in goal for arg in fact[1:]} | (kit & set(state.objects))
    keep |= {f[1] for f in state.by_predicate.get(HOLDING, ())}
    parent = {f[1]: f[2] for f in state.by_predicate.get("in", ())}
    for name in list(keep):
        while name in parent and parent[name] not in keep:
            name = parent[name]
            keep.add(name)
    objects = tuple(o for o in state.objects if o in keep)
    return State(objects, frozenset(f for f in state.facts if all(a in keep for a in f[1:])))


def _up_to_names(domain: Path, state: State, goal: Sequence[Fact], kit: frozenset[str]
                 ) -> tuple[tuple, dict[str, str]]:
    """The search problem with every object outside the kit renamed (the goal's first, in its order), so that
    boiling the penne and boiling the rice from the same kitchen are one search; and each alias's real name."""
    aliases: dict[str, str] = {}
    for name in [a for fact in goal for a in fact[1:]] + sorted(state.objects, key=lambda o: (_shape(state, o), o)):
        if name not in kit and name not in aliases:
            aliases[name] = f"#{len(aliases)}"  # no object is named so

    def renamed(fact: Fact) -> Fact:
        return (fact[0], *(aliases.get(a, a) for a in fact[1:]))

    key = (domain, frozenset(map(renamed, state.facts)), tuple(map(renamed, goal)))
    return key, {alias: real for real, alias in aliases.items()}


def _shape(state: State, name: str) -> tuple:
    """What is true of an object, its own name left out: objects alike in every fact are renamed in name order."""
    return tuple(sorted(tuple("*" if a == name else a for a in fact) for fact in state.facts if name in fact[1:]))


def _renamed(actions: list | None, names: Mapping[str, str]) -> list | None:
    return None if actions is None else [(n, tuple(names.get(a, a) for a in args)) for n, args in actions]


def _solve(domain: Path, state: State, goal: tuple[Fact, ...], time_limit: float):
    # heavy: unified-planning (~1 s) loads with the first search, not with the world model
    from unified_planning.engines import PlanGenerationResultStatus as Status
    from unified_planning.shortcuts import OneshotPlanner

    problem = build_problem(domain, state, goal)
    with OneshotPlanner(name=ENGINE, params=ENGINE_OPTIONS) as engine:
        result = engine.solve(problem, timeout=time_limit)
    if result.status not in (Status.SOLVED_SATISFICING, Status.SOLVED_OPTIMALLY):
        return None
    return [(a.action.name, tuple(str(p) for p in a.actual_parameters)) for a in result.plan.actions]


def build_problem(domain: Path, state: State, goal: Sequence[Fact]):
    """unified-planning's Problem: the domain as its reader read it, the state's objects and facts, the goal."""
    # heavy: unified-planning (~1 s) loads only when a problem is built (a search, --pddl)
    from unified_planning.model import Object
    from unified_planning.shortcuts import And, Exists, Or, Variable

    template = _domain_problem(domain)
    problem = template.clone()
    problem.name = "cook2ltl"
    kind = problem.user_types[0]
    objects = {name: Object(name, kind) for name in state.objects}
    problem.add_objects(objects.values())
    fluents = {fluent.name: fluent for fluent in problem.fluents}
    for name, *args in state.facts:
        problem.set_initial_value(fluents[name](*(objects[a] for a in args)), True)
    for name, *args in goal:
        fact = fluents[name](*(objects[a] for a in args))
        if name == INSIDE:  # directly, or in something there (the milk in a bowl in the fridge)
            middle = Variable("middle", kind)
            x, y = (objects[a] for a in args)
            fact = Or(fact, Exists(And(fluents[name](x, middle), fluents[name](middle, y)), middle))
        problem.add_goal(fact)
    return problem


@cache
def _domain_problem(domain: Path):
    """The domain for search: an action without effects (THOR's Pass) is left out, as it could only stall
    a search (and Fast Downward's reader refuses an action with no :effect)."""
    problem = read_with_unified_planning(domain)
    useful = [action for action in problem.actions if action.effects]
    problem.clear_actions()
    problem.add_actions(useful)
    return problem


def as_calls(world: World, state: State, goal: Sequence[Fact], actions) -> tuple[Call, ...]:
    """The planner's actions as plan lines; processes in a row are one wait, for the state they bring."""
    calls: list[Call] = []
    for name, args in actions:
        if not name.startswith(PROCESS):
            call = Call(name, args)
        elif calls and calls[-1].is_wait:
            continue  # the wait just written let every process act already
        else:
            call = Call(WAIT, _waited_for(world, state, goal, name, args))
        calls.append(call)
        state = world.apply(state, call).state
    return tuple(calls)


def _waited_for(world: World, state: State, goal: Sequence[Fact], name: str, args: tuple[str, ...]
                ) -> tuple[str, str]:
    """What a wait is for: the goal fact time brings about, else the first state the planner's process brings."""
    after = world.passed(state)
    new = after.facts - state.facts
    wanted = [f for f in goal if f in new and len(f) == 2]
    if not wanted:
        schema = world.domain.schemas[name]
        added, _ = effects_of(schema, dict(zip(schema.parameters, args)), state)
        wanted = sorted(f for f in added if len(f) == 2) or sorted(f for f in new if len(f) == 2)
    if not wanted:
        return "timer", "5_minutes"
    predicate, subject = wanted[0]
    return subject, predicate
