"""Micro-benchmarks: span model per sentence, language model per reduction, reductions decoded in one batch
against one after the other, LTL progression per step, kitchen per action, the app's cold start (a fresh
interpreter to its first screen), the demo recipe translated in a fresh app from an empty library, and where a
cold translation's time goes (the model, the kitchen check, the world model, parsing, the rest).

Models are loaded before the clock starts, except for the cold start and the demo recipe in the app, which
count the loading.
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from cook2ltl import paths
from cook2ltl.assembly.backends import load_model
from cook2ltl.assembly.translators import TranslateOptions, open_translator
from cook2ltl.assembly.trial import TrialDone, reference_formula, run_trial
from cook2ltl.bench.backends import parsers
from cook2ltl.bench.ltl import measure_ltl
from cook2ltl.bench.results import write
from cook2ltl.bench.table1 import eval_recipes
from cook2ltl.domain.actions import Action
from cook2ltl.execution.launcher import start_embedded
from cook2ltl.execution.tasks import find_task
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline.records import TranslationFinished
from cook2ltl.pipeline.translator import translate
from cook2ltl.preprocess import split_sentences
from cook2ltl.reduce.action import parameter
from cook2ltl.reduce.llm import LanguageModel
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.reduction import ReductionSettings, reduce_action

# Actions reduced for the language model's timings: the paper's four AI2-THOR tasks (primitive set, verb, what).
REDUCTIONS = (("ai2thor", "microwave", "the potato"), ("ai2thor", "chop", "the tomato"),
              ("ai2thor", "cut", "the bread"), ("ai2thor", "refrigerate", "the apple"))
# Reduced alone and in one batch: one primitive set, so every lane shares one static prompt (as a recipe's do).
BATCH = REDUCTIONS + (("ai2thor", "toast", "the bread"), ("ai2thor", "wash", "the apple"),
                      ("ai2thor", "slice", "the lettuce"), ("ai2thor", "cook", "the egg"))
PAPER_TASKS = ("microwave-potato", "chop-tomato", "cut-bread", "refrigerate-apple")
# A fresh interpreter imports the app, builds its production services and waits for the first screen.
APP_START = """
import asyncio, sys, time
started = time.perf_counter()
from cook2ltl.ui.app import Cook2LTLApp
from cook2ltl.ui.services import production_services
imported = time.perf_counter()

async def first_screen():
    app = Cook2LTLApp(production_services())
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.pause()
        painted = time.perf_counter()
        print(imported - started, painted - started, type(app.screen).__name__)

asyncio.run(first_screen())
"""
# A fresh interpreter opens the app on a recipe (stdin) as `make run` does, the model (argv) first in its Model
# select, presses Run and waits until the finished translation's formulas are on the screen; one JSON line out.
APP_DEMO = """
import asyncio, json, sys, time
started = time.perf_counter()
from cook2ltl import offline
offline.enforce()
from textual.worker import Worker, WorkerState
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.ui.app import Cook2LTLApp
from cook2ltl.ui.messages import TranslationDone, WorkStopped
from cook2ltl.ui.services import production_services
from cook2ltl.ui.widgets.formulas import FormulaList

model, timeout, text = sys.argv[1], float(sys.argv[2]), sys.stdin.read()

async def demo():
    services, settings, ended = production_services(), load_settings(), asyncio.Event()
    services.model_names = (model, *(name for name in services.model_names if name != model))
    finished, failed = [], []

    def hook(message):
        if isinstance(message, Worker.StateChanged) and message.state == WorkerState.ERROR:
            failed.append(f"{type(message.worker.error).__name__}: {message.worker.error}")
        elif isinstance(message, TranslationDone):
            finished.append(message.translation)
        elif not isinstance(message, WorkStopped):
            return
        ended.set()

    app = Cook2LTLApp(services, text, None, settings.keymap, settings.translate)
    async with app.run_test(size=(120, 40), message_hook=hook) as pilot:
        await pilot.pause()
        painted = time.perf_counter()
        await pilot.press("ctrl+r")
        await asyncio.wait_for(ended.wait(), timeout)
        formulas = app.screen.query_one(FormulaList)
        while finished and formulas.whole is None:
            await pilot.pause()  # the hook runs before the screen's handler: wait until it has drawn them
        shown = time.perf_counter()
        record = {"seconds": shown - started, "first_screen_seconds": painted - started,
                  "formulas_shown": len(formulas.steps)}
        if finished:
            stats = finished[0].stats
            record.update(steps=len(finished[0].steps), actions=stats.actions, llm_calls=stats.llm_calls,
                          repair_calls=stats.repair_calls)
        else:
            record["error"] = failed[0] if failed else "stopped"
        print(json.dumps(record))

asyncio.run(demo())
"""


def span_model(sentences: list[str]) -> dict:
    """Milliseconds per sentence, all in one batch as `parse` gives a recipe's sentences."""

    backends = parsers()
    started = time.perf_counter()
    backends.spans.extract(sentences)
    return {"sentences": len(sentences), "ms_per_sentence": 1000 * (time.perf_counter() - started) / len(sentences),
            "load_seconds": backends.load_seconds}


def language_model(name: str, count: int) -> dict:
    """Seconds per reduction and tokens per second over the first `count` actions of REDUCTIONS (the first
    one apart when there are more: it also evaluates the static prompt prefix, or restores it from disk)."""

    model = load_model(name)
    started = time.perf_counter()
    model.complete("", "x", 'root ::= "x"', 1)
    load = time.perf_counter() - started
    usages = []
    for set_name, verb, what in REDUCTIONS[:count]:
        action = Action(verb, (parameter("what", what),))
        usages.append(reduce_action(action, load_primitives(set_name), [], model, ReductionSettings()).usage)
    warm = usages[1:] or usages
    seconds = sum(u.seconds for u in warm)
    decoding = sum(u.seconds - u.prompt_seconds for u in warm)
    return {
        "model": name, "reductions": len(usages), "load_seconds": load,
        "first_reduction_seconds": usages[0].seconds,
        "seconds_per_reduction": statistics.mean(u.seconds for u in warm),
        "completion_tokens_per_second": sum(u.completion_tokens for u in warm) / seconds,
        "prompt_seconds_per_reduction": statistics.mean(u.prompt_seconds for u in warm),
        "decoding_tokens_per_second": sum(u.completion_tokens for u in warm) / decoding if decoding else None,
        "tokens_per_second": sum(u.prompt_tokens + u.completion_tokens for u in warm) / seconds,  # prompt read too
        "prompt_tokens_per_reduction": statistics.mean(u.prompt_tokens for u in warm),
        "completion_tokens_per_reduction": statistics.mean(u.completion_tokens for u in warm),
    }


def batch_decoding(name: str, lanes: int, count: int) -> dict:
    """Seconds for the first `count` actions of BATCH reduced one after the other by a plain model, then from
    `count` threads at once by a model decoding `lanes` of them in one batch. Each model first reduces the first
    action outside the timings (the weights read, the static prompt evaluated), so both time the actions only."""
    jobs = [(load_primitives(set_name), Action(verb, (parameter("what", what),)))
            for set_name, verb, what in BATCH[:count]]

    def reduce(model: LanguageModel, job) -> tuple[str, ...]:
        primitives, action = job
        return tuple(call.text() for call in reduce_action(action, primitives, [], model, ReductionSettings()).body)

    plain = load_model(name)
    reduce(plain, jobs[0])
    started, cpu = time.perf_counter(), time.process_time()
    alone = [reduce(plain, job) for job in jobs]
    alone_seconds, alone_cpu = time.perf_counter() - started, time.process_time() - cpu
    del plain  # one copy of the weights in memory at a time
    batched = load_model(name, lanes=lanes)
    try:
        reduce(batched, jobs[0])
        started, cpu = time.perf_counter(), time.process_time()
        with ThreadPoolExecutor(count) as pool:  # more threads than lanes: the rest wait for a free lane
            together = list(pool.map(lambda job: reduce(batched, job), jobs))
        batched_seconds, batched_cpu = time.perf_counter() - started, time.process_time() - cpu
    finally:
        batched.close()
    return {"model": name, "reductions": count, "lanes": lanes, "alone_seconds": alone_seconds,
            "batched_seconds": batched_seconds, "speedup": alone_seconds / batched_seconds,
            # every thread's CPU seconds, to read beside the wall times on a shared machine
            "alone_cpu_seconds": alone_cpu, "batched_cpu_seconds": batched_cpu,
            "identical_plans": sum(a == b for a, b in zip(alone, together))}


def translation_shares(model_name: str, text: str, echo: Callable[[str], None]) -> dict:
    """Where a cold translation's time goes: `text` translated from an empty library with the defaults of
    `cook2ltl translate` (the recipe set, AR+𝔸, the world model, the kitchen check where the rule wants it)."""
    backends, model = parsers(), load_model(model_name)
    model.complete("", "x", 'root ::= "x"', 1)  # the weights are read outside the timings
    with tempfile.TemporaryDirectory() as folder, open_translator(
            load_primitives("recipe"), model, Path(folder) / "library.sqlite", TranslateOptions(), echo) as translator:
        started = time.perf_counter()
        parsed = parse_recipe(text, backends.spans, backends.dependencies)
        parsing = time.perf_counter() - started
        translation = next(e.translation for e in translate(parsed, translator) if isinstance(e, TranslationFinished))
    stats = translation.stats
    parts = {"model": stats.llm_seconds, "kitchen": stats.kitchen_seconds, "world model": stats.world_seconds,
             "parsing": parsing}
    total = parsing + stats.seconds
    parts["rest"] = total - sum(parts.values())
    return {"model": model_name, "seconds": total, "actions": stats.actions, "llm_calls": stats.llm_calls,
            "repair_calls": stats.repair_calls, "parts_seconds": parts,
            "shares": {part: seconds / total for part, seconds in parts.items()}}


def kitchen_actions(task_ids: tuple[str, ...]) -> dict:
    """Seconds per executed action of the tasks' hand-written plans in the embedded kitchen (no model)."""

    started = time.perf_counter()
    kitchen = start_embedded("FloorPlan1")
    start = time.perf_counter() - started
    seconds = actions = 0.0
    try:
        for task_id in task_ids:
            task = find_task(task_id)
            trial = next(e.trial for e in run_trial(kitchen, reference_formula(task), task.scene, task)
                         if isinstance(e, TrialDone))
            seconds, actions = seconds + trial.rollout.seconds, actions + len(trial.rollout.steps)
    finally:
        kitchen.stop()
    return {"tasks": list(task_ids), "actions": actions, "seconds_per_action": seconds / actions,
            "kitchen_start_seconds": start}


def app_cold_start(repeats: int) -> dict:
    """Seconds from a fresh interpreter to the app's first screen (median of `repeats`)."""
    imports, painted, screen = [], [], ""
    for _ in range(repeats):
        done = subprocess.run([sys.executable, "-c", APP_START], capture_output=True, text=True, timeout=300)
        if done.returncode != 0:
            return {"error": done.stderr.strip().splitlines()[-1] if done.stderr.strip() else "failed"}
        first, second, screen = done.stdout.split()[-3:]
        imports.append(float(first))
        painted.append(float(second))
    return {"repeats": repeats, "import_seconds": statistics.median(imports),
            "first_screen_seconds": statistics.median(painted), "first_screen": screen}


def app_demo(model_name: str, text: str, timeout: float = 900) -> dict:
    """Seconds from a fresh interpreter to the app showing every step's formula of `text`, translated with
    `model_name` from an empty library (a temporary file through $COOK2LTL_LIBRARY; the user's is not read)."""
    with tempfile.TemporaryDirectory() as folder:
        env = {**os.environ, "COOK2LTL_LIBRARY": str(Path(folder) / "library.sqlite")}
        try:
            done = subprocess.run([sys.executable, "-c", APP_DEMO, model_name, str(timeout)], input=text,
                                  capture_output=True, text=True, timeout=timeout + 120, env=env)
        except subprocess.TimeoutExpired:
            return {"model": model_name, "error": f"no translation within {timeout + 120:.0f} s"}
    lines = done.stdout.strip().splitlines()
    if done.returncode != 0 or not lines:
        return {"model": model_name, "error": done.stderr.strip().splitlines()[-1] if done.stderr.strip() else "failed"}
    return {"model": model_name, **json.loads(lines[-1])}


def run_micro(model: str, smoke: bool, out: Path, echo: Callable[[str], None]) -> dict:
    sentences = [s.text for _, text in eval_recipes(1 if smoke else None) for s in split_sentences(text)]
    demo = (paths.assets_dir() / "recipes" / "pasta-bake.txt").read_text(encoding="utf-8")
    demo = " ".join(s.text for s in split_sentences(demo)[:2]) if smoke else demo
    steps: list[tuple[str, Callable[[], dict]]] = [
        ("span_model", lambda: span_model(sentences)),
        ("language_model", lambda: language_model(model, 1 if smoke else len(REDUCTIONS))),
        ("batch", lambda: batch_decoding(model, 2 if smoke else 4, 2 if smoke else len(BATCH))),
        ("ltl", lambda: measure_ltl(3 if smoke else 20)),
        ("kitchen", lambda: kitchen_actions(PAPER_TASKS[:1] if smoke else PAPER_TASKS)),
        ("app", lambda: app_cold_start(1 if smoke else 3)),
        ("translation", lambda: translation_shares(model, demo, echo)),
        ("app_demo", lambda: app_demo(model, demo)),
    ]
    record: dict = {}
    for name, measure in steps:
        record[name] = measure()
        echo(f"{name}: {record[name]}")
        write(out, "micro", record, micro_markdown(record))
    return record


def micro_markdown(r: dict) -> str:
    rows = []
    if "span_model" in r:
        s = r["span_model"]
        rows.append(f"| GLiNER span model | {s['ms_per_sentence']:.1f} ms / sentence | {s['sentences']} sentences of "
                    f"the 50 recipes; loading {s['load_seconds']:.1f} s |")
    if "language_model" in r:
        m = r["language_model"]
        rows.append(f"| LLM reduction ({m['model']}) | {m['seconds_per_reduction']:.2f} s / reduction, "
                    f"{m['tokens_per_second']:.0f} tokens / s ({m['completion_tokens_per_second']:.1f} completion) "
                    f"| first {m['first_reduction_seconds']:.1f} s (with the prompt prefix); "
                    f"{m['prompt_tokens_per_reduction']:.0f} prompt + {m['completion_tokens_per_reduction']:.0f} "
                    f"completion tokens; loading {m['load_seconds']:.1f} s |")
        if m.get("decoding_tokens_per_second"):
            rows.append(f"| … prompt and decoding | {m['prompt_seconds_per_reduction']:.2f} s prompt / reduction, "
                        f"{m['decoding_tokens_per_second']:.1f} tokens / s decoding | the prompt's tail beyond the "
                        f"cached static part, then one token at a time under the grammar |")
    if "batch" in r:
        b = r["batch"]
        rows.append(f"| batch decoding ({b['model']}) | {b['speedup']:.2f}x: {b['alone_seconds']:.1f} s alone, "
                    f"{b['batched_seconds']:.1f} s batched | {b['reductions']} reductions, {b['lanes']} lanes; "
                    f"{b['identical_plans']} of {b['reductions']} plans identical |")
    if "ltl" in r:
        t = r["ltl"]
        rows.append(f"| LTL progression | {t['progress_ms_per_step_cold']['median']:.3f} ms / step cold, "
                    f"{t['progress_ms_per_step_warm']['median']:.4f} warm | {t['formula_nodes']}-node recipe formula, "
                    f"{t['trace_steps']} steps; DFA of 30 actions {t['dfa_sequence_ms']['median']:.1f} ms |")
    if "kitchen" in r:
        k = r["kitchen"]
        rows.append(f"| rollout in the embedded kitchen | {k['seconds_per_action']:.3f} s / action | "
                    f"{k['actions']:.0f} actions of {len(k['tasks'])} reference plans; kitchen start "
                    f"{k['kitchen_start_seconds']:.1f} s |")
    if "app" in r:
        a = r["app"]
        rows.append(f"| app cold start | {a['first_screen_seconds']:.2f} s to the first screen | imports "
                    f"{a['import_seconds']:.2f} s; median of {a['repeats']} fresh interpreters |" if "error" not in a
                    else f"| app cold start | not measured | {a['error']} |")
    if "translation" in r:
        t = r["translation"]
        shares = ", ".join(f"{part} {share:.0%}" for part, share in t["shares"].items())
        rows.append(f"| a cold translation of the demo recipe ({t['model']}) | {t['seconds']:.1f} s | {shares}; "
                    f"{t['actions']} actions, {t['llm_calls']} model calls + {t['repair_calls']} repairs |")
    if "app_demo" in r:
        d, what = r["app_demo"], f"the demo recipe in the app, cold (empty library) ({r['app_demo']['model']})"
        rows.append(f"| {what} | not measured | {d['error']} |" if "error" in d else
                    f"| {what} | {d['seconds']:.1f} s to every formula shown | first screen "
                    f"{d['first_screen_seconds']:.2f} s; {d['formulas_shown']} formulas of {d['steps']} steps, "
                    f"{d['llm_calls']} model calls + {d['repair_calls']} repairs for {d['actions']} actions; a fresh "
                    f"interpreter, models loaded |")
    return "| what | speed | notes |\n|---|---|---|\n" + "\n".join(rows) + "\n"
