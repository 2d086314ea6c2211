"""Plan quality and speed of action reduction per model: the paper's examples and its 4 AI2-THOR tasks.

Each task is one action reduced from scratch (no library) under the grammar; a plan passes when it has the
task's key calls in order (extra calls are allowed). Seconds are the model's, per reduction: the first reduction
of a primitive set also evaluates the static prompt prefix (cold), later ones reuse it from the KV cache (warm).
Every setting is run without and with the paper's comment lines.
"""

from __future__ import annotations

import re
import statistics
import time
from collections.abc import Callable
from pathlib import Path
from typing import NamedTuple

from cook2ltl.assembly.backends import load_model
from cook2ltl.bench.results import write
from cook2ltl.domain.actions import Action
from cook2ltl.reduce.action import parameter
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.reduction import ReductionSettings, reduce_action

MODELS = ("smollm2-135m", "qwen2.5-coder-1.5b")  # compared when no --model is named (the README's table)


class ReductionTask(NamedTuple):
    primitives: str
    verb: str
    arguments: tuple[tuple[str, str], ...]  # (category, text)
    key_calls: tuple[str, ...]  # regular expressions, in order


TASKS = (
    ReductionTask("recipe", "boil", (("what", "eggs"),),
         (r"put\((eggs|water), (pot|saucepan)\)", r"turn_on\(stovetop\)",
          r"wait\(\w+ == (boiled|boiling|cooked|done)\)")),
    ReductionTask("recipe", "blend", (("what", "the mix"), ("time", "until slushy")),
         (r"put\(mix, blender\)", r"turn_on\(blender\)", r"wait\(mix == slushy\)")),
    ReductionTask("recipe", "preheat", (("what", "the oven"), ("temperature", "350 degrees")),
         (r"turn_on\(oven\)", r"wait\(oven == (preheated|hot|350_degrees)\)")),
    ReductionTask("recipe", "simmer", (("what", "the sauce"), ("time", "for 20 minutes")),
         (r"turn_on\(stovetop\)", r"wait\(timer == 20_minutes\)")),
    ReductionTask("recipe", "melt", (("what", "the butter"), ("where", "a saucepan")),
         (r"put\(butter, saucepan\)", r"turn_on\(stovetop\)", r"wait\(butter == melted\)")),
    ReductionTask("recipe", "chop", (("what", "the onion"),), (r"pick_up\(knife\)", r"cut\(onion\)")),
    ReductionTask("recipe", "drain", (("what", "the pasta"),), (r"(pour|put)\(pasta, (colander|sieve|sink)\)",)),
    ReductionTask("recipe", "whisk", (("what", "the eggs"), ("where", "a bowl")),
         (r"(put|pour)\(eggs, bowl\)", r"stir\(eggs\)")),
    ReductionTask("recipe", "refrigerate", (("what", "the dough"), ("time", "until firm")),
         (r"open\(fridge\)", r"put\(dough, fridge\)", r"wait\(dough == firm\)")),
    ReductionTask("ai2thor", "microwave", (("what", "the potato"),),
         (r"open\(microwave\)", r"put\(potato, microwave\)", r"close\(microwave\)", r"turn_on\(microwave\)")),
    ReductionTask("ai2thor", "chop", (("what", "the tomato"),), (r"pick_up\(knife\)", r"slice\(tomato\)")),
    ReductionTask("ai2thor", "cut", (("what", "the bread"),), (r"pick_up\(knife\)", r"slice\(bread\)")),
    ReductionTask("ai2thor", "refrigerate", (("what", "the apple"),),
         (r"open\(fridge\)", r"pick_up\(apple\)", r"put\(apple, fridge\)", r"close\(fridge\)")),
)
# Two short plans of one set, so the smoke pass has a cold and a warm reduction: seconds with smollm2.
SMOKE_TASKS = tuple(t for t in TASKS if t.primitives == "ai2thor" and t.verb in ("chop", "cut"))


def key_calls_found(lines: list[str], keys: tuple[str, ...]) -> int:
    """How many of the key calls appear, in order."""
    found, position = 0, 0
    for key in keys:
        hit = next((i for i in range(position, len(lines)) if re.fullmatch(key, lines[i])), None)
        if hit is None:
            continue
        found, position = found + 1, hit + 1
    return found


def reduce_tasks(model_name: str, comments: bool, tasks: tuple[ReductionTask, ...], echo: Callable[[str], None],
                 cold_prefix: bool = True) -> dict:
    """Every task reduced by one model: plans passed, share of key calls found, seconds, tokens, and each plan.
    With `cold_prefix` (what the table reports) the static prompt prefix is evaluated, never restored from disk."""
    model = load_model(model_name)
    if cold_prefix:
        model.state_dir = None
    started = time.perf_counter()
    model.complete("", "x", 'root ::= "x"', 1)  # load the weights outside the timings
    load_seconds = time.perf_counter() - started
    plans, warm, cold = [], [], []
    last_set = None
    for task in tasks:
        action = Action(task.verb, tuple(parameter(category, text) for category, text in task.arguments))
        reduction = reduce_action(action, load_primitives(task.primitives), [], model,
                                  ReductionSettings(comments=comments))
        lines = [call.text() for call in reduction.body]
        found = key_calls_found(lines, task.key_calls)
        (cold if task.primitives != last_set else warm).append(reduction.usage.seconds)
        last_set = task.primitives
        plans.append({"primitives": task.primitives, "action": action.text(), "plan": lines, "key_calls_found": found,
                      "key_calls": len(task.key_calls), "seconds": reduction.usage.seconds,
                      "completion_tokens": reduction.usage.completion_tokens})
        mark = "pass" if found == len(task.key_calls) else f"{found}/{len(task.key_calls)}"
        echo(f"  {task.primitives:8} {action.text():28} {reduction.usage.seconds:5.1f}s {mark:5} {'; '.join(lines)}")
    return {
        "model": model_name, "comments": comments, "passed": sum(p["key_calls_found"] == p["key_calls"] for p in plans),
        "key_calls_found_share": statistics.mean(p["key_calls_found"] / p["key_calls"] for p in plans),
        "warm_seconds_median": statistics.median(warm), "cold_seconds_mean": statistics.mean(cold),
        "completion_tokens_mean": statistics.mean(p["completion_tokens"] for p in plans),
        "load_seconds": load_seconds, "plans": plans,
    }


def run_reduce(models: tuple[str, ...], smoke: bool, out: Path, echo: Callable[[str], None]) -> dict:
    """Each model without and with comment lines, written after each. Smoke: without, on SMOKE_TASKS, the
    prompt prefix restored from disk when it can be (the pass checks the path, its seconds mean nothing)."""
    tasks = SMOKE_TASKS if smoke else TASKS
    record: dict = {"models": list(models), "tasks": len(tasks), "rows": []}
    for name in models:
        for comments in (False,) if smoke else (False, True):
            echo(f"{name}, comments {'on' if comments else 'off'}:")
            record["rows"].append(reduce_tasks(name, comments, tasks, echo, cold_prefix=not smoke))
            write(out, "reduce", record, reduce_markdown(record))
    return record


def reduce_markdown(record: dict) -> str:
    header = (f"| model | comments | plans passed (of {record['tasks']}) | key calls found "
              "| s/reduction (warm, median) | s/reduction (cold prefix) | completion tokens | load s |")
    lines = [header, "|---" * 8 + "|"]
    for r in record["rows"]:
        lines.append(f"| {r['model']} | {'on' if r['comments'] else 'off'} | {r['passed']} "
                     f"| {r['key_calls_found_share']:.0%} | {r['warm_seconds_median']:.1f} "
                     f"| {r['cold_seconds_mean']:.1f} | {r['completion_tokens_mean']:.0f} | {r['load_seconds']:.1f} |")
    return "\n".join(lines) + "\n"
