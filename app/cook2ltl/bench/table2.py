"""The paper's Table II: kitchen tasks planned by a language model, AR against AR+𝔸, success and seconds.

Each task of assets/tasks/ is planned from its instruction by Algorithm 1 with the ai2thor primitives and rolled
out in its kitchen (the embedded one, through ai2thor's Controller), `runs` consecutive times, as in the paper.
The action library starts empty (a temporary file) and is shared by every run and task, so with AR+𝔸 the first
run of a verb asks the model and later runs reuse its plan. A third column is cook2ltl's own AR+𝔸: each new
plan is first run in the kitchen and a refused one goes back to the model with THOR's reasons, up to twice
(`cook2ltl translate`'s default; cook2ltl.reduce.repair). The model is deterministic (temperature 0, fixed
seed): the runs of a task agree unless the library changed in between. Success is the task's goal holding at the
end. Seconds per rollout are planning (parse and reduction) plus execution; loading the models is counted apart.
"""

from __future__ import annotations

import statistics
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from cook2ltl.assembly.backends import load_model
from cook2ltl.assembly.planning import PRIMITIVES, TaskPlanner
from cook2ltl.assembly.translators import TranslateOptions, build_translator
from cook2ltl.assembly.trial import TrialDone, explain, run_trial
from cook2ltl.bench.backends import parsers
from cook2ltl.bench.results import pm, write
from cook2ltl.errors import UserError
from cook2ltl.execution.kitchen_check import KitchenValidator
from cook2ltl.execution.launcher import start_embedded
from cook2ltl.execution.tasks import PARAPHRASES, load_tasks, set_up
from cook2ltl.library import Library
from cook2ltl.pipeline.records import Variant
from cook2ltl.reduce.primitives import load_primitives

# Table II of the paper (gpt-3.5-turbo, 5 sets of 10 runs): successes of 10 and seconds, AR then AR+𝔸.
PAPER = {
    "microwave-potato": ((5.4, 27.29), (8, 3.26)),
    "chop-tomato": ((2.4, 16.0), (4, 1.61)),
    "cut-bread": ((9, 12.85), (8, 1.12)),
    "refrigerate-apple": ((7.6, 14.6), (8, 1.56)),
}
# all: tasks.toml's 33 (paper and suite); paraphrase: paraphrases.toml's; smoke: the first paper task only
TASK_SETS = ("paper", "suite", "all", "paraphrase", "smoke")
REPAIR = "AR+A repair"
WORLD = "AR+A world"
# Each column: the pipeline's variant, how many repairs a plan the kitchen refuses gets (None: not checked),
# and whether plans are decoded, checked and completed in the world model (the grounding ablation).
COLUMNS = {"AR": (Variant.AR, None, False), "AR+A": (Variant.AR_LIBRARY, None, False),
           REPAIR: (Variant.AR_LIBRARY, 2, False), WORLD: (Variant.AR_LIBRARY, None, True)}


def choose_tasks(which: str):
    def set_of(task) -> str:
        if task.source.startswith("paper"):
            return "paper"
        return "paraphrase" if task.source == PARAPHRASES else "suite"

    if which not in TASK_SETS:
        raise UserError(f"unknown task set {which!r}", f"choose from {', '.join(TASK_SETS)}.")
    wanted = {"all": ("paper", "suite"), "smoke": ("paper",)}.get(which, (which,))
    tasks = [t for t in load_tasks() if set_of(t) in wanted]
    return tasks[:1] if which == "smoke" else tasks


def run_task(kitchen, planner, task) -> dict:
    """Plan the task's instruction, roll the plan out, check the goal."""

    kitchen.reset(task.scene)
    set_up(kitchen, task)  # the world model starts from the kitchen as the task leaves it (a dirty mug)
    plan = planner.plan(task.instruction, task.scene, kitchen.last_event.metadata["objects"])
    outcome = {"plan": [c.text() for c in plan.calls], "sources": list(plan.sources),
               "llm_calls": plan.stats.llm_calls, "repair_calls": plan.stats.repair_calls, "plan_seconds": plan.seconds}
    try:
        trial = next(e.trial for e in run_trial(kitchen, plan.formula, task.scene, task, plan)
                     if isinstance(e, TrialDone))
    except UserError as error:  # the plan names something the kitchen lacks: the plan fails
        return {**outcome, "success": False, "verdict": None, "reason": error.message, "rollout_seconds": 0.0,
                "actions": 0}
    unmet = [c.text() for c, met in trial.goal.conditions if not met]
    reason = f"goal not met: {'; '.join(unmet)} ({explain(trial.rollout)})" if unmet else explain(trial.rollout)
    return {**outcome, "success": trial.success, "verdict": trial.rollout.verdict.value, "reason": reason,
            "rollout_seconds": trial.rollout.seconds, "actions": len(trial.rollout.steps)}


def rollout_runs(model: str, variant: Variant, runs: int, tasks, echo: Callable[[str], None],
                 repairs: int | None = None, ground: bool = False) -> dict:
    """Every task `runs` consecutive times with one planner and one library; each run's outcome. With
    `repairs`, new plans are checked in the kitchen and repaired that many times at most."""

    results: dict[str, list[dict]] = {}
    started = time.perf_counter()
    backends, language_model = parsers(), load_model(model)
    language_model.complete("", "x", 'root ::= "x"', 1)  # the weights are read outside the timings
    load_seconds = time.perf_counter() - started
    checked = ("" if repairs is None else f", kitchen check and {repairs} repairs") + (", world model" if ground else "")
    echo(f"{model}, {variant.value}{checked}, {runs} runs per task; models loaded in {load_seconds:.1f} s")
    primitives = load_primitives(PRIMITIVES)
    with tempfile.TemporaryDirectory() as folder, KitchenValidator(primitives) as validator:
        library = Library(Path(folder) / "library.sqlite") if variant == Variant.AR_LIBRARY else None
        # Without repairs the benchmark measures the plans as written: no kitchen check either.
        options = TranslateOptions(variant, check=repairs is not None, repairs=repairs or 0, ground=False)
        translator = build_translator(primitives, language_model, library, options, lambda _: validator, echo)
        planner = TaskPlanner(translator, backends.spans, backends.dependencies, ground)
        kitchen = start_embedded("FloorPlan1")
        try:
            for task in tasks:
                rows = results[task.id] = [run_task(kitchen, planner, task) for _ in range(runs)]
                failed = next((r["reason"] for r in rows if not r["success"]), "")
                echo(f"{task.id:<20} {sum(r['success'] for r in rows):>2}/{runs}  "
                     f"{statistics.mean(_seconds(r) for r in rows):6.2f} s/rollout  {' · '.join(rows[0]['plan'])}"
                     + (f"\n{'':<20} ✗ {failed}" if failed else ""))
        finally:
            kitchen.stop()
            if library is not None:
                library.close()
    return {"model": model, "variant": variant.value, "repairs": repairs, "ground": ground, "runs": runs,
            "load_seconds": round(load_seconds, 3), "tasks": results}


def summary(name: str, rows: list[dict], runs: int) -> str:
    wins = sum(r["success"] for r in rows)
    seconds = [_seconds(r) for r in rows]
    firsts = [s for i, s in enumerate(seconds) if i % runs == 0]
    later = [s for i, s in enumerate(seconds) if i % runs] or [0.0]
    return (f"{name}: success {wins}/{len(rows)} ({100 * wins / len(rows):.0f} %); seconds per rollout "
            f"{statistics.mean(seconds):.2f} (first run {statistics.mean(firsts):.2f}, "
            f"later runs {statistics.mean(later):.2f})")


def run_table2(model: str, runs: int, which: str, out: Path, echo: Callable[[str], None],
               columns: tuple[str, ...] = tuple(COLUMNS)) -> dict:
    """AR, AR+𝔸 and AR+𝔸 with repairs (or some of them), each from an empty library; the record and the table."""
    unknown = set(columns) - set(COLUMNS)
    if unknown:
        raise UserError(f"unknown Table II variant(s) {', '.join(sorted(unknown))}",
                        f"choose from {', '.join(COLUMNS)}.")
    tasks = choose_tasks(which)
    record = {"model": model, "runs": runs, "tasks": [t.id for t in tasks], "variants": {}}
    for name, (variant, repairs, ground) in [(name, COLUMNS[name]) for name in COLUMNS if name in columns]:
        record["variants"][name] = rollout_runs(model, variant, runs, tasks, echo, repairs, ground)
        write(out, "table2", record, table2_markdown(record))
    return record


def table2_markdown(record: dict) -> str:
    variants = record["variants"]
    lines = ["| task | AR success | AR s / rollout | AR+𝔸 success | AR+𝔸 s / rollout | AR+𝔸 with repairs: success "
             "| s / rollout | AR+𝔸 in the world model: success | s / rollout | paper AR: successes · s "
             "| paper AR+𝔸: successes · s |", "|---" * 11 + "|"]
    for task in record["tasks"]:
        cells = []
        for variant in COLUMNS:
            rows = variants.get(variant, {}).get("tasks", {}).get(task)
            cells += [f"{sum(r['success'] for r in rows)}/{len(rows)}", pm([_seconds(r) for r in rows])] if rows \
                else ["—", "—"]
        paper = PAPER.get(task)
        paper_cells = [f"{p[0]}/10 · {p[1]}" for p in paper] if paper else ["—", "—"]
        lines.append(f"| {task} | {' | '.join(cells)} | {' | '.join(paper_cells)} |")
    notes = [summary(f"{name}, all tasks", [r for rows in v["tasks"].values() for r in rows], v["runs"])
             for name, v in variants.items()]
    return "\n".join(lines) + f"\n\n{record['model']}; {record['runs']} consecutive runs per task.\n" + \
        "".join(f"- {note}\n" for note in notes)


def _seconds(row: dict) -> float:
    return row["plan_seconds"] + row["rollout_seconds"]
