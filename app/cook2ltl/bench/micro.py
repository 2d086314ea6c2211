"""Micro-benchmarks: span model per sentence, language model per reduction, LTL progression per step, kitchen
per action, the app's cold start (a fresh interpreter to its first screen), and where a cold translation's
time goes (the model, the kitchen check, the world model, parsing, the rest).

Models are loaded before the clock starts, except for the cold start, which is all about loading.
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
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
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.reduction import ReductionSettings, reduce_action

# Actions reduced for the language model's timings: the paper's four AI2-THOR tasks (primitive set, verb, what).
REDUCTIONS = (("ai2thor", "microwave", "the potato"), ("ai2thor", "chop", "the tomato"),
              ("ai2thor", "cut", "the bread"), ("ai2thor", "refrigerate", "the apple"))
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


def run_micro(model: str, smoke: bool, out: Path, echo: Callable[[str], None]) -> dict:
    sentences = [s.text for _, text in eval_recipes(1 if smoke else None) for s in split_sentences(text)]
    demo = (paths.assets_dir() / "recipes" / "pasta-bake.txt").read_text(encoding="utf-8")
    demo = " ".join(s.text for s in split_sentences(demo)[:2]) if smoke else demo
    steps: list[tuple[str, Callable[[], dict]]] = [
        ("span_model", lambda: span_model(sentences)),
        ("language_model", lambda: language_model(model, 1 if smoke else len(REDUCTIONS))),
        ("ltl", lambda: measure_ltl(3 if smoke else 20)),
        ("kitchen", lambda: kitchen_actions(PAPER_TASKS[:1] if smoke else PAPER_TASKS)),
        ("app", lambda: app_cold_start(1 if smoke else 3)),
        ("translation", lambda: translation_shares(model, demo, echo)),
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
    return "| what | speed | notes |\n|---|---|---|\n" + "\n".join(rows) + "\n"
