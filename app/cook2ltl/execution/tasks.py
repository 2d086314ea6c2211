"""Kitchen tasks with goal conditions: assets/tasks/tasks.toml, and paraphrases.toml (held-out paraphrased and
compound instructions, to measure how the method generalises).

A task is an instruction ("Microwave the potato."), the kitchen it runs in,
and goal conditions on THOR object state defined beforehand, as in the
paper's Sec. V-C: success means the goal holds when the rollout ends. Each
condition names an object type (or one objectId) and THOR metadata fields;
it holds when some object of that type, or a piece of one, has them all:

    goal = [{ object = "Potato", isCooked = true, in = "Microwave" }]

`in` is a receptacle type or objectId among the object's parentReceptacles;
`isSliced = true` also counts the pieces slicing leaves (TomatoSliced). A task
may `setup` the scene first with THOR actions (make the mug dirty to wash it),
and carries a hand-written `reference` plan that shows the goal is reachable.
"""

from __future__ import annotations

import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from types import MappingProxyType
from typing import Any

from cook2ltl import paths
from cook2ltl.errors import UserError
from cook2ltl.execution.executor import Kitchen, send
from cook2ltl.world.thor_facts import PREDICATES
from cook2ltl.world.thor_names import Obj, piece_types

# THOR metadata fields a goal may test, and `in` for the receptacle.
FIELDS = frozenset({
    "isCooked", "temperature", "isSliced", "isDirty", "isFilledWithLiquid", "fillLiquid", "isToggled", "isOpen",
    "isBroken", "isUsedUp", "in",
})  # fmt: skip
CATEGORIES = ("heat", "cool", "slice", "clean", "fill", "put", "toggle")
PARAPHRASES = "cook2ltl paraphrases"  # the source of paraphrases.toml's tasks


@dataclass(frozen=True)
class GoalCondition:
    object: str  # a THOR object type, or one objectId
    state: Mapping[str, Any]  # field -> value

    def __post_init__(self) -> None:
        object.__setattr__(self, "state", MappingProxyType(dict(self.state)))

    def text(self) -> str:
        fields = ", ".join(f"{k} = {_value(v)}" for k, v in self.state.items())
        return f"{self.object}: {fields}"


@dataclass(frozen=True)
class Task:
    id: str
    instruction: str
    scene: str
    category: str
    source: str
    goal: tuple[GoalCondition, ...]
    setup: tuple[Mapping[str, str], ...] = ()  # {action = "DirtyObject", object = "Mug"}
    reference: tuple[str, ...] = ()  # plan lines in the ai2thor primitives


@dataclass(frozen=True)
class GoalCheck:
    conditions: tuple[tuple[GoalCondition, bool], ...]

    @property
    def met(self) -> bool:
        return all(ok for _, ok in self.conditions)


def tasks_file() -> Path:
    return paths.assets_dir() / "tasks" / "tasks.toml"


def paraphrases_file() -> Path:
    return paths.assets_dir() / "tasks" / "paraphrases.toml"


def load_tasks(path: Path | None = None) -> tuple[Task, ...]:
    """The tasks of `path`; by default tasks.toml's, then paraphrases.toml's."""
    if path is not None:
        return _load(path)
    return _unique(_load(tasks_file()) + _load(paraphrases_file()), f"{tasks_file()} and {paraphrases_file()}")


@cache
def _load(path: Path) -> tuple[Task, ...]:
    try:
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError) as error:
        raise UserError(f"Cannot read the tasks file {path}: {error}", "see assets/tasks/README.md.") from error
    return _unique(tuple(_task(entry, path) for entry in raw.get("task", [])), str(path))


def _unique(tasks: tuple[Task, ...], where: str) -> tuple[Task, ...]:
    ids = [t.id for t in tasks]
    duplicates = sorted({i for i in ids if ids.count(i) > 1})
    if duplicates:
        raise UserError(f"{where}: task ids used twice: {', '.join(duplicates)}.")
    return tasks


def find_task(text: str, tasks: Sequence[Task] | None = None) -> Task | None:
    """The task whose id or instruction is `text` (case, spaces and a final period do not matter)."""
    wanted = _normal(text)
    return next((t for t in tasks or load_tasks() if wanted in (_normal(t.id), _normal(t.instruction))), None)


def check_goal(task: Task, objects: Sequence[Obj]) -> GoalCheck:
    return GoalCheck(tuple((c, condition_met(c, objects)) for c in task.goal))


def condition_met(condition: GoalCondition, objects: Sequence[Obj]) -> bool:
    types = {o["objectId"]: o["objectType"] for o in objects}
    return any(_has(o, condition.state, types) for o in _candidates(condition.object, objects))


def preferred_objects(task: Task, objects: Sequence[Obj]) -> frozenset[str]:
    """The objectIds the goal names, so a name that fits several objects picks these."""
    named = {c.object for c in task.goal} | {c.state["in"] for c in task.goal if "in" in c.state}
    return frozenset(o["objectId"] for o in objects if o["objectId"] in named)


def set_up(kitchen: Kitchen, task: Task) -> None:
    """Run the task's setup actions on the first object of each named type; UserError if THOR refuses."""
    for step in task.setup:
        objects = kitchen.last_event.metadata["objects"]
        target = next((o["objectId"] for o in objects if o["objectType"] == step["object"]), None)
        if target is None:
            raise UserError(f"Task {task.id}: no {step['object']} to {step['action']} in {task.scene}.")
        call, _ = send(kitchen, {"action": step["action"], "objectId": target, "forceAction": True})
        if not call.success:
            raise UserError(f"Task {task.id}: setup {step['action']} {target} failed: {call.error}")


def task_json(task: Task) -> dict:
    return {"id": task.id, "instruction": task.instruction, "scene": task.scene, "category": task.category,
            "source": task.source, "goal": [c.text() for c in task.goal]}


def goal_json(check: GoalCheck) -> dict:
    return {"met": check.met, "conditions": [{"condition": c.text(), "met": ok} for c, ok in check.conditions]}


def _candidates(name: str, objects: Sequence[Obj]) -> list[Obj]:
    if "|" in name:
        return [o for o in objects if o["objectId"] == name or o["objectId"].startswith(name + "|")]
    piece = piece_types().get(name)
    return [o for o in objects if o["objectType"] in (name, piece)]


def _has(o: Obj, state: Mapping[str, Any], types: Mapping[str, str]) -> bool:
    for field, value in state.items():
        if field == "in":
            parents = o.get("parentReceptacles") or ()
            if not any(value in (p, types.get(p)) for p in parents):
                return False
        elif field == "isSliced":
            if PREDICATES["sliced"](o) != value:
                return False
        elif o.get(field) != value:
            return False
    return True


def _task(entry: Mapping[str, Any], path: Path) -> Task:
    def bad(message: str) -> UserError:
        return UserError(f"{path}: task {entry.get('id', '?')!r}: {message}", "see assets/tasks/README.md.")

    missing = [k for k in ("id", "instruction", "scene", "category", "source", "goal") if k not in entry]
    if missing:
        raise bad(f"missing {', '.join(missing)}.")
    if entry["category"] not in CATEGORIES:
        raise bad(f"category must be one of {', '.join(CATEGORIES)}.")
    goal = []
    for raw in entry["goal"]:
        fields = {k: v for k, v in raw.items() if k != "object"}
        unknown = sorted(set(fields) - FIELDS)
        if "object" not in raw or not fields or unknown:
            raise bad(f"a goal condition needs an object and some of {', '.join(sorted(FIELDS))}"
                      + (f" (unknown: {', '.join(unknown)})" if unknown else "") + ".")
        goal.append(GoalCondition(raw["object"], fields))
    setup = tuple(MappingProxyType(dict(s)) for s in entry.get("setup", []))
    if any(set(s) != {"action", "object"} for s in setup):
        raise bad("a setup step is { action = \"DirtyObject\", object = \"Mug\" }.")
    return Task(entry["id"], entry["instruction"], entry["scene"], entry["category"], entry["source"],
                tuple(goal), setup, tuple(entry.get("reference", ())))


def _normal(text: str) -> str:
    return " ".join(text.lower().split()).rstrip(".").strip()


def _value(value: Any) -> str:
    return str(value).lower() if isinstance(value, bool) else str(value)
