"""The paper's Table I: the ablation AR* / AR / AR+𝔸 over its 50 evaluation recipes.

Every run parses the recipes once, then translates them with each variant in VARIANTS order: AR+𝔸 from an
empty library growing over the 50 recipes; AR+𝔸 again against the library it grew (the warm rerun); AR+𝔸 in
approved-only mode against that library once a reviewer ("bench") has approved the entries whose plans passed
the kitchen check; AR (primitives passed through); AR* (every action reduced); and AR+𝔸 with repairs (a plan
the kitchen refuses goes back to the model twice, as `cook2ltl translate` does) from an empty library. The
model decodes greedily, so what differs between runs is the order in which the library meets the recipes:
the first run takes the file's order, each later one a shuffle seeded by its run's seed. AR and AR* do not
depend on the order, so their runs differ in time only. AR+𝔸 in the world model (from an empty library of its
own) decodes every new reduction against the recipe set's world model, where the recipe has got to, and lets
the planner complete it; there the world model is the judge, so its row reports how many new reductions
reach their intended effect, and how many lines the planner wrote.

Every new reduction is run in the kitchen (cook2ltl.execution.kitchen_check) without changing what is cached or
which actions reach the model (no repairs, except in the repair variant): the validated rate is the share of
new reductions whose plan the kitchen ran. Time is the translation's without those checks.

Executability is the paper's: the fraction of the actions of the generated plans that are admissible, the
library's plans included. An admissible action is a primitive call that fits the primitive set; inadmissible
ones are the model's dropped lines and one for every recipe action left without an admissible plan. The
pipeline's own `rates` (model lines only, library hits not counted) is kept beside it as `line_executability`.
"""

from __future__ import annotations

import csv
import random
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path

from cook2ltl import paths
from cook2ltl.assembly.backends import load_model
from cook2ltl.assembly.translators import TranslateOptions, build_translator
from cook2ltl.bench.backends import parsers
from cook2ltl.bench.refusals import refusals, refusals_note
from cook2ltl.bench.results import pm, write
from cook2ltl.domain.actions import Source
from cook2ltl.domain.recipe import ParsedRecipe
from cook2ltl.errors import UserError
from cook2ltl.execution.kitchen_check import KitchenValidator
from cook2ltl.formulas.formula import direct_calls
from cook2ltl.library import Library
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline.rates import rates
from cook2ltl.pipeline.records import Translation, Variant
from cook2ltl.pipeline.side_by_side import translate_side_by_side
from cook2ltl.pipeline.translator import Translator
from cook2ltl.reduce.action import actions_of
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.validation import PlanValidator

RECIPES_FILE = "eval_recipes_50.csv"
COLD, WARM, APPROVED, REPAIR, WORLD = "AR+A", "AR+A warm", "AR+A approved-only", "AR+A repair", "AR+A world"
# What the library saves first, then the paper's baselines, the costly repairs last; WARM and APPROVED need
# COLD's library.
VARIANTS = (COLD, WARM, APPROVED, "AR", "AR*", WORLD, REPAIR)
SMOKE_VARIANTS = (COLD, WARM, "AR*")  # the other variants' logic is covered by the unit tests
REVIEWER = "bench"
FIRST_SEED = 4242  # its run keeps the file's order of the recipes
REPAIRS = 2
# Table I of the paper (gpt-3.5-turbo, 10 runs): executability, minutes, API calls.
PAPER = {"AR*": (0.91, 14.85, 275), "AR": (0.92, 9.89, 231), "AR+A": (0.94, 6.05, 134)}
LABELS = {"AR*": "AR* (reduce every action)", "AR": "AR (skip primitives)", COLD: "AR+𝔸 (library from empty)",
          WARM: "AR+𝔸 warm rerun (grown library)", APPROVED: "AR+𝔸 approved-only (checked plans approved)",
          REPAIR: "AR+𝔸 with repairs (library from empty)", WORLD: "AR+𝔸 in the world model (library from empty)"}


@dataclass(frozen=True)
class Stage:
    """The parsed recipes and the backends shared by every run."""

    numbers: tuple[str, ...]
    recipes: tuple[ParsedRecipe, ...]
    load_seconds: float  # span model and dependency parser
    parse_seconds: float


def recipes_file() -> Path:
    """The evaluation recipes: the project's copy (tests/data), else the shared original."""
    candidates = [paths.PROJECT_ROOT / "tests" / "data" / RECIPES_FILE,
                  paths.shared_data_dir() / "cook2ltl" / RECIPES_FILE]
    found = next((path for path in candidates if path.is_file()), None)
    if found is None:
        raise UserError(f"The evaluation recipes ({RECIPES_FILE}) are not here: looked at "
                        f"{', '.join(str(p) for p in candidates)}.",
                        "run from a checkout of cook2ltl, or set $COOK2LTL_SHARED_DATA to the folder that holds "
                        f"cook2ltl/{RECIPES_FILE}.")
    return found


def eval_recipes(limit: int | None = None) -> list[tuple[str, str]]:
    """(number, edited text) of the paper's evaluation recipes, in the file's order."""
    with recipes_file().open(encoding="utf-8") as handle:
        rows = [(row["Number"], row["Edited text"]) for row in csv.DictReader(handle)]
    return rows[:limit]


def parse_all(recipes: list[tuple[str, str]]) -> Stage:
    backends = parsers()
    started = time.perf_counter()
    parsed = tuple(parse_recipe(text, backends.spans, backends.dependencies) for _, text in recipes)
    return Stage(tuple(n for n, _ in recipes), parsed, backends.load_seconds, time.perf_counter() - started)


def library_bound(stage: Stage, primitives) -> dict:
    """What bounds AR+𝔸's calls with exact keys: the library is keyed by verb and signature, so every distinct key
    among the actions that are not passed through as primitives costs at least one call, however good the model.
    Reusing an entry across verbs the verb-effect table reads as one action and across signatures (the default,
    `library.reuse`) can go below it."""

    actions = [a for recipe in stage.recipes for step in recipe.steps for frame in step.frames
               for a in actions_of(frame)]
    passed = [a for a in actions if primitives.get(a.verb) and direct_calls(a, primitives.get(a.verb)) is not None]
    reduced = [a for a in actions if a not in passed]
    return {"actions": len(actions), "primitive": len(passed), "reduced_by_ar": len(reduced),
            "distinct_keys": len({(a.verb, a.signature) for a in reduced}),
            "distinct_verbs": len({a.verb for a in reduced})}


def plan_admissibility(translation: Translation) -> tuple[int, int]:
    """(admissible, inadmissible) actions of a recipe's generated plans; an action the world model found
    already done needs none and counts neither way."""
    admissible = inadmissible = 0
    for step in translation.steps:
        for result in step.actions:
            if result.reduction.source == Source.WORLD:
                continue
            admissible += len(result.plan)
            inadmissible += len(result.reduction.dropped) + (0 if result.plan else 1)
    return admissible, inadmissible


def run_variant(stage: Stage, translators: list[Translator], progress: Callable[[dict], None]) -> dict:
    """One variant over every recipe, side by side with several translators: summed statistics, both
    executabilities, validated rate, per-recipe calls, and the time it took from start to end."""
    totals: dict[str, float] = {"admissible": 0, "inadmissible": 0, "check_seconds": 0.0}
    translations, per_recipe = [], []
    started = time.perf_counter()
    for index, translation in translate_side_by_side(stage.recipes, translators):
        number = stage.numbers[index]
        translations.append(translation)
        admissible, inadmissible = plan_admissibility(translation)
        totals["admissible"] += admissible
        totals["inadmissible"] += inadmissible
        totals["check_seconds"] += sum(r.validation.seconds for s in translation.steps for r in s.actions
                                       if r.validation is not None)
        for key, value in vars(translation.stats).items():
            totals[key] = totals.get(key, 0) + value
        per_recipe.append({"recipe": number, "actions": translation.stats.actions,
                           "llm_calls": translation.stats.llm_calls, "cross_reuses": translation.stats.cross_reuses,
                           "seconds": round(translation.stats.seconds, 3)})
        totals["elapsed_seconds"] = time.perf_counter() - started
        progress(_summary(totals, translations, stage) | {"per_recipe": per_recipe})
    return _summary(totals, translations, stage) | {"per_recipe": per_recipe, "workers": len(translators)}


def _summary(totals: dict[str, float], translations: list[Translation], stage: Stage) -> dict:
    planned = totals["admissible"] + totals["inadmissible"]
    counts = rates(*translations)
    return {
        **{key: round(value, 3) if isinstance(value, float) else value for key, value in totals.items()},
        "executability": totals["admissible"] / planned if planned else 0.0,
        "line_executability": counts.executability, "new_reductions": counts.new_reductions,
        "validated_rate": counts.validated_rate, "refusals": refusals(translations), **world_counts(translations),
        # The recipes' parse is shared by the variants of a run; each variant's time includes it.
        "wall_seconds": round(totals.get("elapsed_seconds", 0.0) - totals["check_seconds"] + stage.parse_seconds, 3),
        "recipes_done": len(translations),
    }


def world_counts(translations: list[Translation]) -> dict:
    """New reductions checked in the world model: how many reach their intended effect (with a plan), how many
    had no effect the world observes, how many applied as the model wrote them, and the planner's lines."""
    new = [r for t in translations for s in t.steps for r in s.actions
           if r.reduction.source == Source.LLM and r.check is not None]
    if not new:
        return {}
    return {"world_new": len(new), "world_reached": sum(1 for r in new if r.plan and r.check.effect_reached),
            "world_no_effect": sum(1 for r in new if not r.check.effect),
            "world_as_written": sum(1 for r in new if r.check.applicable and r.check.planner_lines == 0 and r.plan),
            "world_planner_lines": sum(r.check.planner_lines for r in new)}


def in_run_order(stage: Stage, seed: int) -> Stage:
    """The recipes in the order a run meets them: the file's for the first seed, else shuffled by `seed`."""
    if seed == FIRST_SEED:
        return stage
    order = list(range(len(stage.recipes)))
    random.Random(seed).shuffle(order)
    return replace(stage, numbers=tuple(stage.numbers[i] for i in order),
                   recipes=tuple(stage.recipes[i] for i in order))


def run_table1(model_name: str, runs: int, variants: tuple[str, ...], limit: int | None, out: Path,
               echo: Callable[[str], None], seed: int = FIRST_SEED, primitive_set: str = "recipe", workers: int = 1
               ) -> dict:
    """Table I with the real models, runs seeded `seed`, `seed` + 1, …; the record and table are rewritten
    after each recipe."""

    check_variants(variants)
    recipes = eval_recipes(limit)
    stage = parse_all(recipes)
    echo(f"{len(recipes)} recipes parsed in {stage.parse_seconds:.1f} s (models loaded in {stage.load_seconds:.1f} s)")
    model, primitives = load_model(model_name, lanes=workers), load_primitives(primitive_set)
    started = time.perf_counter()
    model.complete("", "x", 'root ::= "x"', 1)  # the weights are read outside the timings
    record = {"model": model_name, "recipes": len(recipes), "primitives": primitives.name, "workers": workers,
              "parse_seconds": round(stage.parse_seconds, 3), "load_seconds": round(stage.load_seconds, 3),
              "llm_load_seconds": round(time.perf_counter() - started, 3), "runs": [],
              "library_bound": library_bound(stage, primitives)}

    def report(rows: list[dict]) -> None:
        write(out, "table1", record | {"runs": rows}, table1_markdown(rows, len(recipes), record["library_bound"]))


    with KitchenValidator(primitives) as validator:
        record["runs"] = measure(stage, model, primitives, validator, runs, variants, seed, report, echo, workers)
    return record


def check_variants(variants: tuple[str, ...]) -> None:
    unknown = set(variants) - set(VARIANTS)
    if unknown:
        raise UserError(f"unknown variant(s) {', '.join(sorted(unknown))}", f"choose from {', '.join(VARIANTS)}.")
    if {WARM, APPROVED} & set(variants) and COLD not in variants:
        raise UserError("the warm rerun and approved-only mode reuse the library that AR+A grows in the same run",
                        "ask for AR+A too (it runs first).")


def measure(stage: Stage, model, primitives, validator: PlanValidator, runs: int, variants: tuple[str, ...],
            seed: int, report: Callable[[list[dict]], None], echo: Callable[[str], None], workers: int = 1
            ) -> list[dict]:
    """Each run (its own seed, recipe order and empty libraries) over the variants in VARIANTS order; `report`
    gets every row so far after each recipe, the running one last. The world variant translates `workers`
    recipes side by side."""

    rows: list[dict] = []
    for index in range(runs):
        run_seed = seed + index
        run_stage = in_run_order(stage, run_seed)
        with tempfile.TemporaryDirectory() as folder:
            grown, fresh = Library(Path(folder) / "grown.sqlite"), Library(Path(folder) / "repair.sqlite")
            own = Library(Path(folder) / "world.sqlite")
            opened = [grown, fresh, own]
            try:
                for name in [v for v in VARIANTS if v in variants]:
                    if name == APPROVED:
                        approve_checked(grown)
                    variant = Variant(name) if name in ("AR", "AR*") else Variant.AR_LIBRARY
                    library = {REPAIR: fresh, WORLD: own}.get(name, grown if variant == Variant.AR_LIBRARY else None)
                    # Every variant's new reductions run in the kitchen; the world variant's where the rule says.
                    options = TranslateOptions(variant, check=None if name == WORLD else True,
                                               repairs=REPAIRS if name == REPAIR else 0,
                                               approved_only=name == APPROVED, ground=name == WORLD)
                    translators = [build_translator(primitives, model, library, options, lambda _: validator, echo)]
                    if name == WORLD:  # no kitchen checks (one THOR kitchen serves one thread): side by side
                        more = [Library(own.path) for _ in range(workers - 1)]
                        opened.extend(more)
                        translators += [replace(build_translator(primitives, model, extra, options, lambda _: validator,
                                                                 echo), grounding=translators[0].grounding)
                                        for extra in more]  # one world and planner, its searches shared
                    head = {"variant": name, "model": model.name, "seed": run_seed}
                    rows.append(head | run_variant(run_stage, translators, lambda partial: report(rows + [head | partial])))
                    report(rows)
                    echo(f"run {index + 1} {name:<18} calls {rows[-1]['llm_calls']:>4}  executability "
                         f"{rows[-1]['executability']:.3f}  {rows[-1]['wall_seconds'] / 60:.2f} min")
            finally:
                for library in opened:
                    library.close()
    return rows


def approve_checked(library) -> int:
    """Approve every pending entry whose plan passed the kitchen check, as a reviewer trusting the check would."""
    chosen = [e for e in library.entries() if e.status.value == "pending" and e.validation == "passed"]
    for entry in chosen:
        library.set_status(entry.id, "approved", by=REVIEWER)
    return len(chosen)


def table1_markdown(rows: list[dict], total: int, bound: dict | None = None) -> str:
    """Mean ± std per variant and model over the runs that covered all `total` recipes, beside the paper; a
    variant with no finished run shows its running one, over the recipes it has done."""
    lines = ["| variant | model | runs | executability | validated rate | LLM calls (+ repairs) | prompt tokens "
             "| completion tokens | time (min) | paper: executability · calls · min |", "|---" * 10 + "|"]
    groups: dict[tuple[str, str], list[dict]] = {}
    for row in rows:
        groups.setdefault((row["variant"], row["model"]), []).append(row)
    complete_groups = {key: [r for r in group if r["recipes_done"] == total] for key, group in groups.items()}
    for (variant, model), group in groups.items():
        complete = complete_groups[(variant, model)] or group[-1:]
        if len(complete) == len(group) and complete[0]["recipes_done"] == total:
            runs = f"{len(complete)}"
        elif complete[0]["recipes_done"] == total:
            runs = f"{len(complete)} (+{len(group) - len(complete)} partial)"
        else:
            runs = f"partial: {complete[0]['recipes_done']} of {total} recipes"
        paper = PAPER.get(variant)
        paper_cell = f"{paper[0]:.2f} · {paper[2]} · {paper[1]:.2f}" if paper else "—"
        rates_ = [r["validated_rate"] for r in complete if r.get("validated_rate") is not None]
        repairs = [r.get("repair_calls", 0) for r in complete]
        lines.append(
            f"| {LABELS[variant]} | {model} | {runs} | {pm([r['executability'] for r in complete])} "
            f"| {pm(rates_) if rates_ else '—'} | {pm([r['llm_calls'] for r in complete], 0)}"
            + (f" (+ {pm(repairs, 0)})" if any(repairs) else "")
            + f" | {pm([r['prompt_tokens'] for r in complete], 0)} "
            f"| {pm([r['completion_tokens'] for r in complete], 0)} "
            f"| {pm([r['wall_seconds'] / 60 for r in complete])} | {paper_cell} |")
    notes = _ratios(groups, total) + "".join(world_note(model, group or groups[(variant, model)][-1:])
                                             for (variant, model), group in complete_groups.items() if variant == WORLD)
    refused = "".join(refusals_note(f"{LABELS[variant]}, {model}", group[0].get("refusals", {}))
                      for (variant, model), group in complete_groups.items() if group and variant in (COLD, REPAIR))
    return ("\n".join(lines) + "\n" + notes + (bound_note(bound) if bound else "")
            + (f"\n{refused}" if refused else ""))


def world_note(model: str, rows: list[dict]) -> str:
    rows = [r for r in rows if r.get("world_new")]
    if not rows:
        return ""
    reached = [r["world_reached"] / r["world_new"] for r in rows]
    as_written = [r["world_as_written"] / r["world_new"] for r in rows]
    return (f"\n{model}, AR+𝔸 in the world model: {pm(reached)} of the new reductions reach their intended effect "
            f"({pm([r['world_reached'] for r in rows], 0)} of {pm([r['world_new'] for r in rows], 0)}; "
            f"{pm([r['world_no_effect'] for r in rows], 0)} with no effect the world observes); "
            f"{pm(as_written)} reach it as the model wrote them; the planner wrote "
            f"{pm([r['world_planner_lines'] for r in rows], 0)} lines; the model wrote the effects of "
            f"{pm([r.get('effect_calls', 0) for r in rows], 0)} verbs the table lacks.\n")


def bound_note(bound: dict) -> str:
    keys, reduced, actions = bound["distinct_keys"], bound["reduced_by_ar"], bound["actions"]
    return (f"\nThe library is keyed by verb and signature: of {actions} actions, {bound['primitive']} pass through "
            f"as primitives and {reduced} reach the library with {keys} distinct keys ({bound['distinct_verbs']} "
            f"verbs), so with exact keys alone AR+𝔸 needs at least {keys} calls: {keys / reduced:.2f} × AR, "
            f"{keys / actions:.2f} × AR*. Reusing an entry across verbs the verb-effect table reads as one action "
            f"and across signatures (the default; `translate --exact-keys` turns it off) can go below it.\n")


def _ratios(groups: dict[tuple[str, str], list[dict]], total: int) -> str:
    """The library's saving in calls against AR* and AR, per model; a baseline still running is compared over
    the recipes both have done (the counts do not depend on the seed, so one run of each is enough)."""
    notes = []
    for model in dict.fromkeys(m for _, m in groups):
        rows = {v: max(group, key=lambda r: r["recipes_done"]) for (v, m), group in groups.items() if m == model}
        if COLD not in rows:
            continue
        parts = []
        for baseline in ("AR*", "AR"):
            if baseline not in rows:
                continue
            done = min(rows[COLD]["recipes_done"], rows[baseline]["recipes_done"])
            cold, base = (sum(r["llm_calls"] for r in rows[v]["per_recipe"][:done]) for v in (COLD, baseline))
            if base:
                prefix = "" if done == total else f" over the first {done} recipes"
                parts.append(f"{cold / base:.2f} × {'the calls of ' if not parts else ''}{baseline}{prefix}")
        if parts:
            notes.append(f"{model}: AR+𝔸 makes {', '.join(parts)} (paper: 0.49 × AR*, 0.58 × AR).")
    return ("\n" + "\n".join(notes) + "\n") if notes else ""
