"""The kitchen check of the new reductions of the paper's 50 evaluation recipes, without and with repairs.

    .venv/bin/python bench/translate_50.py [--model qwen2.5-coder-1.5b] [--repairs 0 2] [--limit 50] [--out bench/results]
    .venv/bin/python bench/translate_50.py --summarize bench/results/validation-*.jsonl   # a run cut short

The recipes (tests/data/eval_recipes_50.csv, column "Edited text") are parsed once with the real parser;
AR+A starts from an empty library and grows it over the 50 recipes in order, as in the paper. The ablation
itself (Table I: AR*, AR, AR+A) is `cook2ltl bench table1`.

AR+A runs once per --repairs value with the kitchen validator: the share of new reductions
whose plan runs in the THOR kitchen (validated rate), beside the paper's executability. Each recipe's
results are appended to <out>/validation-<model>-repairs<N>.jsonl as soon as it is done, so a run cut
short still leaves its figures; the summary goes to validation-<model>.json and .md.
"""

from __future__ import annotations

import argparse
import csv
import json
import signal
import sys
import tempfile
import time
import traceback
from pathlib import Path

from cook2ltl import offline
from cook2ltl.library import Library
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline import Finished, Translation, Translator, rates, translate
from cook2ltl.reduce.llm import DEFAULT_MODEL, load_model
from cook2ltl.reduce.model import Source
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.validation import KitchenValidator
from cook2ltl.settings import load_settings
from cook2ltl.stack import dependency_parser, span_extractor

RECIPES = Path(__file__).resolve().parents[1] / "tests" / "data" / "eval_recipes_50.csv"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default=DEFAULT_MODEL)
    parser.add_argument("--limit", type=int, default=50)
    parser.add_argument("--repairs", nargs="+", type=int, default=[0, 2])
    parser.add_argument("--out", type=Path, default=Path(__file__).resolve().parent / "results")
    parser.add_argument("--threads", type=int, help="llama.cpp threads (default: one per core); 1 on a shared machine")
    parser.add_argument("--summarize", nargs="+", type=Path, help="only summarize these per-recipe logs")
    args = parser.parse_args()
    if args.summarize:
        print(_table([summary_of_log(path) for path in args.summarize]))
        return
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # a killed run still stops its kitchen
    offline.enforce()
    with RECIPES.open(encoding="utf-8") as handle:
        texts = [row["Edited text"] for row in csv.DictReader(handle)][: args.limit]
    spans, dependencies = span_extractor(load_settings()), dependency_parser()
    started = time.perf_counter()
    parsed = [parse_recipe(text, spans, dependencies) for text in texts]
    print(f"{len(parsed)} recipes parsed in {time.perf_counter() - started:.0f} s", flush=True)
    model, primitives = load_model(args.model), load_primitives("recipe")
    model.threads = args.threads or model.threads
    validation_runs(parsed, model, primitives, args.repairs, args.out)


def validation_runs(parsed, model, primitives, repairs: list[int], out: Path) -> None:
    out.mkdir(parents=True, exist_ok=True)
    summaries = []
    for count in repairs:
        log = out / f"validation-{model.name}-repairs{count}.jsonl"
        log.unlink(missing_ok=True)
        translations, errors = [], 0
        with tempfile.TemporaryDirectory() as folder, KitchenValidator(primitives) as validator:
            library = Library(Path(folder) / "library.sqlite")
            translator = Translator(primitives, model, library, validator=validator, repairs=count)
            for index, recipe in enumerate(parsed):
                try:
                    translations.append(_translation(recipe, translator))
                    record = _recipe_record(index, translations[-1])
                except Exception:  # recorded and counted, so one bad recipe does not end an hour-long run
                    record = {"recipe": index, "error": traceback.format_exc()}
                    errors += 1
                    print(record["error"], flush=True)
                with log.open("a", encoding="utf-8") as handle:
                    handle.write(json.dumps(record, ensure_ascii=False) + "\n")
                print(f"repairs {count}: recipe {index + 1}/{len(parsed)} {_line(summary(translations, count))}",
                      flush=True)
            library.close()
        summaries.append({**summary(translations, count), "errors": errors})
        (out / f"validation-{model.name}.json").write_text(json.dumps(
            {"model": model.name, "primitives": primitives.name, "recipes": len(parsed), "runs": summaries},
            indent=2))
        (out / f"validation-{model.name}.md").write_text(_table(summaries))
        print(_table(summaries), flush=True)


def summary(translations: list[Translation], repairs: int) -> dict:
    counts, totals = rates(*translations), _totals(translations)
    new = [r for t in translations for s in t.steps for r in s.actions if r.reduction.source == Source.LLM]
    first_try = sum(1 for r in new if not r.attempts and r.validation is not None and r.validation.passed)
    unchecked = sum(1 for r in new if r.validation is not None and not r.validation.checked)
    return {
        "repairs": repairs, "recipes": len(translations), "actions": totals["actions"],
        "library_hits": totals["library_hits"], "new_reductions": counts.new_reductions,
        "no_plan": sum(1 for r in new if r.validation is None), "checked": totals["checked"],
        "unchecked": unchecked, "validated": counts.validated, "validated_rate": counts.validated_rate,
        "passed_first_try": first_try, "repaired": totals["repaired"], "repair_calls": totals["repair_calls"],
        "executability": counts.executability, "llm_seconds": round(totals["llm_seconds"], 1),
        "seconds": round(totals["seconds"], 1),
    }


def summary_of_log(path: Path) -> dict:
    """The summary of a run from its per-recipe log, however far it got."""
    records = [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines()]
    done = [r for r in records if "error" not in r]
    reductions = [x for r in done for x in r["reductions"]]
    total = {key: sum(r["stats"][key] for r in done) for key in done[0]["stats"]} if done else {}
    admissible = sum(len(x["body"]) + sum(len(a) for a in x["failed_attempts"]) for x in reductions)
    written = admissible + total.get("dropped_lines", 0)
    validated = sum(1 for x in reductions if x["validation"] == "passed")
    return {
        "repairs": int(path.stem.rsplit("repairs", 1)[-1]), "recipes": len(done), "errors": len(records) - len(done),
        "actions": total.get("actions", 0), "library_hits": total.get("library_hits", 0),
        "new_reductions": len(reductions), "no_plan": sum(1 for x in reductions if x["validation"] is None),
        "checked": total.get("checked", 0), "unchecked": sum(1 for x in reductions if x["validation"] == "unchecked"),
        "validated": validated, "validated_rate": validated / len(reductions) if reductions else None,
        "passed_first_try": sum(1 for x in reductions if x["validation"] == "passed" and not x["failed_attempts"]),
        "repaired": total.get("repaired", 0), "repair_calls": total.get("repair_calls", 0),
        "executability": admissible / written if written else None,
        "llm_seconds": round(total.get("llm_seconds", 0), 1), "seconds": round(total.get("seconds", 0), 1),
    }


def _translation(recipe, translator: Translator) -> Translation:
    return next(e for e in translate(recipe, translator) if isinstance(e, Finished)).translation


def _totals(translations: list[Translation]) -> dict[str, float]:
    totals: dict[str, float] = {}
    for translation in translations:
        for key, value in vars(translation.stats).items():
            totals[key] = totals.get(key, 0) + value
    return totals


def _recipe_record(index: int, translation: Translation) -> dict:
    reductions = [{
        "action": r.reduction.action.text(),
        "body": [c.text() for c in r.reduction.body],
        "validation": r.validation.status if r.validation else None,
        "problems": list(r.validation.messages()) if r.validation else [],
        "scene": r.validation.scene if r.validation else None,
        "failed_attempts": [[c.text() for c in a.body] for a in r.attempts],
    } for s in translation.steps for r in s.actions if r.reduction.source == Source.LLM]
    return {"recipe": index, "stats": vars(translation.stats), "reductions": reductions}


def _line(s: dict) -> str:
    rate = f"{s['validated_rate']:.0%}" if s["validated_rate"] is not None else "-"
    return (f"new {s['new_reductions']}, validated {s['validated']} ({rate}), first try {s['passed_first_try']}, "
            f"repaired {s['repaired']}, unchecked {s['unchecked']}, {s['seconds']:.0f} s")


def _table(summaries: list[dict]) -> str:
    rows = ["| repairs | recipes | new reductions | checked | unchecked | no plan | passed first try | repaired "
            "| validated | validated rate | executability | repair calls | LLM s | s |", "|" + "---|" * 14]
    for s in summaries:
        rate = f"{s['validated_rate']:.1%}" if s["validated_rate"] is not None else "-"
        executability = f"{s['executability']:.1%}" if s["executability"] is not None else "-"
        rows.append(f"| {s['repairs']} | {s['recipes']} | {s['new_reductions']} | {s['checked']:.0f} "
                    f"| {s['unchecked']} | {s['no_plan']} | {s['passed_first_try']} | {s['repaired']:.0f} "
                    f"| {s['validated']} | {rate} | {executability} | {s['repair_calls']:.0f} "
                    f"| {s['llm_seconds']:.0f} | {s['seconds']:.0f} |")
    return "\n".join(rows) + "\n"


if __name__ == "__main__":
    main()
