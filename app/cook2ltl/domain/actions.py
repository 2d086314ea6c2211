"""Frozen records of action reduction: primitive sets, actions, plan lines, reductions."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum
from pathlib import Path

CONDITION = "condition"  # the one parameter kind that is not an object: `subject == state` (wait)
TIMER = "timer"  # the subject of a duration: wait(timer == 30_minutes)
WAIT = "wait"  # the primitive that lets time pass until its condition holds: wait(potato == hot)


@dataclass(frozen=True)
class Primitive:
    """An action the robot can execute, e.g. put(what, where)."""

    name: str
    params: tuple[str, ...]

    @property
    def object_arity(self) -> int:
        return sum(1 for param in self.params if param != CONDITION)


@dataclass(frozen=True)
class WorldSpec:
    """Where a primitive set's world model lives: its PDDL domain, the kitchen its plans start in (a kitchen
    file, or THOR's scenes), and the predicates its state words name (`golden` → browned)."""

    domain: Path
    kitchen: Path | None  # None: the AI2-THOR kitchens
    states: tuple[tuple[str, str], ...]  # (word, predicate): hashable, as the set is
    # what the planner may use besides a goal's objects, by goal predicate ("*": always); None: everything
    kit: tuple[tuple[str, tuple[str, ...]], ...] | None = None
    planner: bool = True  # whether a planner completes plans in this world (False: they are checked only)
    # the binary predicate by which the world tells where a liquid is, container first (THOR: filled-with);
    # None: a liquid is a thing like any other, `in` a container and with states of its own
    liquid_fill: str | None = None


@dataclass(frozen=True)
class PrimitiveSet:
    """𝒜: a robot's primitives, the environment's objects and states, and the prompt's example functions."""

    name: str
    primitives: tuple[Primitive, ...]
    objects: tuple[str, ...]
    states: tuple[str, ...]
    examples: str
    source: Path
    world: WorldSpec | None = None  # the set's world model, when its file names one
    # What each primitive does in an AI2-THOR kitchen, for the kitchen check: (primitive, an AI2-THOR
    # primitive or touch or pour); a primitive the AI2-THOR set also has does itself.
    in_thor: tuple[tuple[str, str], ...] = ()

    def get(self, name: str) -> Primitive | None:
        return next((primitive for primitive in self.primitives if primitive.name == name), None)


@dataclass(frozen=True)
class Parameter:
    """One filled category of an action: `name` shows in the function header, `value` is used in the body.

    For objects they are equal ("the penne" → penne); a time "until cold" is named until_cold and its
    value, the state a wait reaches, is cold.
    """

    category: str  # what, where, how, time, temperature
    text: str
    name: str
    value: str

    @property
    def is_object(self) -> bool:
        return self.category in OBJECT_CATEGORIES


OBJECT_CATEGORIES = ("what", "where", "how")


@dataclass(frozen=True)
class Action:
    """A frame as a function call: verb identifier and its parameters, in category order."""

    verb: str
    parameters: tuple[Parameter, ...]

    @property
    def signature(self) -> tuple[str, ...]:
        """Which categories are filled (with repeats): the library's key beside the verb."""
        return tuple(parameter.category for parameter in self.parameters)

    @property
    def objects(self) -> tuple[str, ...]:
        return tuple(dict.fromkeys(p.value for p in self.parameters if p.is_object))

    @property
    def values(self) -> tuple[str, ...]:
        """Time and temperature values, offered to wait conditions as states or durations."""
        return tuple(dict.fromkeys(p.value for p in self.parameters if not p.is_object))

    def text(self) -> str:
        return f"{self.verb}({', '.join(p.value for p in self.parameters)})"


@dataclass(frozen=True)
class Call:
    """One plan line: `put(egg, pot)`, or for a wait the condition's subject and state: wait(water == boiled)."""

    name: str
    args: tuple[str, ...]

    @property
    def is_wait(self) -> bool:
        return self.name == "wait"

    def text(self) -> str:
        if self.is_wait and len(self.args) == 2:
            return f"wait({self.args[0]} == {self.args[1]})"
        return f"{self.name}({', '.join(self.args)})"


class Source(StrEnum):
    PRIMITIVE = "primitive"  # the action is itself in 𝒜
    LIBRARY = "library"  # found in 𝔸
    LLM = "llm"  # reduced now
    WORLD = "world"  # nothing to do: the world model says its effect already holds where it is used


@dataclass(frozen=True)
class Usage:
    prompt_tokens: int = 0
    completion_tokens: int = 0
    seconds: float = 0.0
    prompt_seconds: float = 0.0  # of `seconds`, evaluating the prompt (what the KV cache did not hold)
    choice_seconds: float = 0.0  # besides `seconds`: the caller choosing the lines the world allows, line by line


@dataclass(frozen=True)
class Reduction:
    """An action and the plan that implements it; `dropped` are model lines that were not admissible."""

    action: Action
    body: tuple[Call, ...]
    source: Source
    usage: Usage = Usage()
    dropped: tuple[str, ...] = ()
    prompt_hash: str = ""
    entry_id: int | None = None  # the library row it came from or went to
