"""Success and seconds per rollout of the kitchen tasks, planned by a language model (the paper's Table II).

    .venv/bin/python bench/rollout_bench.py [--runs 10] [--model qwen2.5-coder-1.5b] [--tasks paper|suite|all]
                                            [--variant AR+A|AR] [--json results.json]

Each task of assets/tasks/ is planned from its instruction by Algorithm 1 with the ai2thor primitives and rolled
out in its kitchen (the embedded one, through ai2thor's Controller), `--runs` consecutive times, as in the paper.
The action library starts empty (a temporary file) and is shared by every run and task, so with AR+A the first
run of a verb asks the model and later runs reuse its plan. The model is deterministic (temperature 0, fixed
seed): the runs of a task agree unless the library changed in between. Success is the task's goal holding at the
end. Seconds per rollout are planning (parse and reduction) plus execution; loading the models is counted apart.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

from cook2ltl import offline
from cook2ltl.errors import UserError
from cook2ltl.kitchen.launcher import start_embedded
from cook2ltl.kitchen.planning import open_planner
from cook2ltl.kitchen.tasks import Task, load_tasks
from cook2ltl.kitchen.trial import TrialDone, explain, run_trial
from cook2ltl.pipeline import Variant
from cook2ltl.reduce.llm import DEFAULT_MODEL


def run_task(kitchen, planner, task: Task) -> dict:
    plan = planner.plan(task.instruction)
    outcome = {"plan": [c.text() for c in plan.calls], "sources": list(plan.sources), "plan_seconds": plan.seconds}
    try:
        trial = next(e.trial for e in run_trial(kitchen, plan.formula, task.scene, task, plan)
                     if isinstance(e, TrialDone))
    except UserError as error:  # the plan names something the kitchen lacks: the plan fails
        return {**outcome, "success": False, "verdict": None, "reason": error.message, "rollout_seconds": 0.0}
    unmet = [c.text() for c, met in trial.goal.conditions if not met]
    reason = f"goal not met: {'; '.join(unmet)} ({explain(trial.rollout)})" if unmet else explain(trial.rollout)
    return {**outcome, "success": trial.success, "verdict": trial.rollout.verdict.value, "reason": reason,
            "rollout_seconds": trial.rollout.seconds}


def warm_up(planner) -> float:
    """Load the span model, the parser and the language model before anything is timed."""
    started = time.perf_counter()
    planner.spans.extract(["Warm up the oven."])
    planner.dependencies.parse(["Warm up the oven."])
    planner.translator.model.complete("", "x", 'root ::= "x"', 1)
    return time.perf_counter() - started


def summary(name: str, rows: list[dict], runs: int) -> str:
    wins = sum(r["success"] for r in rows)
    seconds = [r["plan_seconds"] + r["rollout_seconds"] for r in rows]
    firsts = [s for i, s in enumerate(seconds) if i % runs == 0]
    later = [s for i, s in enumerate(seconds) if i % runs] or [0.0]
    return (f"{name}: success {wins}/{len(rows)} ({100 * wins / len(rows):.0f} %); seconds per rollout "
            f"{statistics.mean(seconds):.2f} (first run {statistics.mean(firsts):.2f}, "
            f"later runs {statistics.mean(later):.2f})")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--model", default=DEFAULT_MODEL)
    parser.add_argument("--tasks", choices=("paper", "suite", "all"), default="all")
    parser.add_argument("--variant", type=Variant, choices=(Variant.AR, Variant.AR_LIBRARY), default=Variant.AR_LIBRARY)
    parser.add_argument("--json", type=Path, help="also write every run to this file")
    args = parser.parse_args()
    offline.enforce()
    tasks = [t for t in load_tasks()
             if args.tasks == "all" or (args.tasks == "paper") == t.source.startswith("paper")]
    results: dict[str, list[dict]] = {}
    with tempfile.TemporaryDirectory() as folder, open_planner(args.model, Path(folder) / "library.sqlite",
                                                                 args.variant) as planner:
        print(f"{args.model}, {args.variant.value}, {args.runs} runs per task; models loaded in "
              f"{warm_up(planner):.1f} s", flush=True)
        kitchen = start_embedded("FloorPlan1")
        try:
            for task in tasks:
                rows = results[task.id] = [run_task(kitchen, planner, task) for _ in range(args.runs)]
                wins = sum(r["success"] for r in rows)
                mean = statistics.mean(r["plan_seconds"] + r["rollout_seconds"] for r in rows)
                failed = next((r["reason"] for r in rows if not r["success"]), "")
                print(f"{task.id:<20} {wins:>2}/{args.runs}  {mean:6.2f} s/rollout  {' · '.join(rows[0]['plan'])}"
                      + (f"\n{'':<20} ✗ {failed}" if failed else ""), flush=True)
        finally:
            kitchen.stop()
    paper = [r for t in tasks if t.source.startswith("paper") for r in results[t.id]]
    suite = [r for t in tasks if not t.source.startswith("paper") for r in results[t.id]]
    for name, rows in (("paper tasks", paper), ("suite", suite)):
        if rows:
            print(summary(name, rows, args.runs))
    if args.json:
        args.json.write_text(json.dumps({"model": args.model, "variant": args.variant.value, "runs": args.runs,
                                         "tasks": results}, indent=2, ensure_ascii=False))


if __name__ == "__main__":
    sys.exit(main())
