"""Plan quality and speed of action reduction per model: the paper's examples and its 4 AI2-THOR tasks.

    .venv/bin/python bench/reduce_bench.py [--models smollm2-135m qwen2.5-coder-1.5b] [--comments both]

Each task is one action reduced from scratch (no library) under the grammar; a plan passes when it has
the task's key calls in order (extra calls are allowed). Seconds are the model's, per reduction: the first
reduction of a primitive set also evaluates the static prompt prefix, later ones reuse it from the KV cache.
"""

from __future__ import annotations

import argparse
import re
import statistics
import time

from cook2ltl.reduce.action import parameter
from cook2ltl.assembly.backends import load_model
from cook2ltl.domain.actions import Action
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.reduction import ReductionSettings, reduce_action

# (primitive set, verb, arguments, key calls in order as regular expressions)
TASKS = [
    ("recipe", "boil", [("what", "eggs")],
     [r"put\((eggs|water), (pot|saucepan)\)", r"turn_on\(stovetop\)", r"wait\(\w+ == (boiled|boiling|cooked|done)\)"]),
    ("recipe", "blend", [("what", "the mix"), ("time", "until slushy")],
     [r"put\(mix, blender\)", r"turn_on\(blender\)", r"wait\(mix == slushy\)"]),
    ("recipe", "preheat", [("what", "the oven"), ("temperature", "350 degrees")],
     [r"turn_on\(oven\)", r"wait\(oven == (preheated|hot|350_degrees)\)"]),
    ("recipe", "simmer", [("what", "the sauce"), ("time", "for 20 minutes")],
     [r"turn_on\(stovetop\)", r"wait\(timer == 20_minutes\)"]),
    ("recipe", "melt", [("what", "the butter"), ("where", "a saucepan")],
     [r"put\(butter, saucepan\)", r"turn_on\(stovetop\)", r"wait\(butter == melted\)"]),
    ("recipe", "chop", [("what", "the onion")], [r"pick_up\(knife\)", r"cut\(onion\)"]),
    ("recipe", "drain", [("what", "the pasta")], [r"(pour|put)\(pasta, (colander|sieve|sink)\)"]),
    ("recipe", "whisk", [("what", "the eggs"), ("where", "a bowl")], [r"(put|pour)\(eggs, bowl\)", r"stir\(eggs\)"]),
    ("recipe", "refrigerate", [("what", "the dough"), ("time", "until firm")],
     [r"open\(fridge\)", r"put\(dough, fridge\)", r"wait\(dough == firm\)"]),
    ("ai2thor", "microwave", [("what", "the potato")],
     [r"open\(microwave\)", r"put\(potato, microwave\)", r"close\(microwave\)", r"turn_on\(microwave\)"]),
    ("ai2thor", "chop", [("what", "the tomato")], [r"pick_up\(knife\)", r"slice\(tomato\)"]),
    ("ai2thor", "cut", [("what", "the bread")], [r"pick_up\(knife\)", r"slice\(bread\)"]),
    ("ai2thor", "refrigerate", [("what", "the apple")],
     [r"open\(fridge\)", r"pick_up\(apple\)", r"put\(apple, fridge\)", r"close\(fridge\)"]),
]


def key_calls_found(lines: list[str], keys: list[str]) -> int:
    """How many of the key calls appear, in order."""
    found, position = 0, 0
    for key in keys:
        hit = next((i for i in range(position, len(lines)) if re.fullmatch(key, lines[i])), None)
        if hit is None:
            continue
        found, position = found + 1, hit + 1
    return found


def bench(model_name: str, comments: bool, verbose: bool) -> dict:
    model = load_model(model_name)
    model.state_dir = None  # measure the static prefix evaluated cold, not restored from disk
    started = time.perf_counter()
    model.complete("", "x", 'root ::= "x"', 1)  # load the weights outside the timings
    load_seconds = time.perf_counter() - started
    passed, partial, seconds, cold, tokens = 0, [], [], [], []
    last_set = None
    for set_name, verb, arguments, keys in TASKS:
        primitives = load_primitives(set_name)
        action = Action(verb, tuple(parameter(category, text) for category, text in arguments))
        reduction = reduce_action(action, primitives, [], model, ReductionSettings(comments=comments))
        lines = [call.text() for call in reduction.body]
        found = key_calls_found(lines, keys)
        passed += found == len(keys)
        partial.append(found / len(keys))
        (cold if set_name != last_set else seconds).append(reduction.usage.seconds)
        tokens.append(reduction.usage.completion_tokens)
        last_set = set_name
        if verbose:
            mark = "pass" if found == len(keys) else f"{found}/{len(keys)}"
            print(f"  {set_name:8} {action.text():28} {reduction.usage.seconds:5.1f}s {mark:5} {'; '.join(lines)}")
    return {
        "model": model_name, "comments": comments, "passed": passed, "partial": statistics.mean(partial),
        "warm": statistics.median(seconds), "cold": statistics.mean(cold), "tokens": statistics.mean(tokens),
        "load": load_seconds,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--models", nargs="+", default=["smollm2-135m", "qwen2.5-coder-1.5b"])
    parser.add_argument("--comments", choices=["off", "on", "both"], default="both")
    parser.add_argument("--quiet", action="store_true")
    args = parser.parse_args()
    settings = {"off": [False], "on": [True], "both": [False, True]}[args.comments]
    rows = []
    for name in args.models:
        for comments in settings:
            print(f"{name}, comments {'on' if comments else 'off'}:", flush=True)
            rows.append(bench(name, comments, not args.quiet))
    print(f"\n| model | comments | plans passed (of {len(TASKS)}) | key calls found | s/reduction (warm, median) "
          "| s/reduction (cold prefix) | completion tokens | load s |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['model']} | {'on' if r['comments'] else 'off'} | {r['passed']} | {r['partial']:.0%} | {r['warm']:.1f} "
              f"| {r['cold']:.1f} | {r['tokens']:.0f} | {r['load']:.1f} |")


if __name__ == "__main__":
    main()
