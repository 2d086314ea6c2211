"""The benchmark's own arithmetic, with fake parsers and a scripted model: what Table I counts and prints."""

import json

import pytest

from cook2ltl.bench.results import mean_std, pm, write
from cook2ltl.bench.table1 import (
    FIRST_SEED,
    VARIANTS,
    Stage,
    check_variants,
    in_run_order,
    library_bound,
    measure,
    table1_markdown,
)
from cook2ltl.bench.table2 import TASK_SETS, choose_tasks, table2_markdown
from cook2ltl.errors import UserError
from cook2ltl.parse import parse_recipe
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.validation import LineProblem, Validation
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel

RECIPES = {
    "1": ("Boil the egg. Put the egg in a bowl.",
          {"Boil the egg.": [("VERB", "Boil"), ("WHAT", "the egg")],
           "Put the egg in a bowl.": [("VERB", "Put"), ("WHAT", "the egg"), ("WHERE", "a bowl")]}),
    "2": ("Boil the potato. Fry the onion. Melt the butter.",
          {"Boil the potato.": [("VERB", "Boil"), ("WHAT", "the potato")],
           "Fry the onion.": [("VERB", "Fry"), ("WHAT", "the onion")],
           "Melt the butter.": [("VERB", "Melt"), ("WHAT", "the butter")]}),
}
BOIL = "turn_on(stovetop)\nturn_off(stovetop)"  # admissible for any object
FRY = "fry(onion)\nexplode(onion)"  # nothing admissible: two dropped lines and no plan
MELT = "turn_on(stovetop)"  # admissible, but the fake kitchen refuses one-line plans


class OneLinersFail:
    """A kitchen check that passes plans of two lines or more."""

    def __init__(self):
        self.checked = []

    def validate(self, action, plan, so_far=None):
        self.checked.append(action.verb)
        return Validation(len(plan) > 1, () if len(plan) > 1 else (LineProblem(1, plan[0].text(), "too short"),),
                          "FloorPlan1", 0.25)

    def close(self):
        pass


def stage() -> Stage:
    parsed = tuple(parse_recipe(text, ScriptedSpans(spans), ScriptedDependencies()) for text, spans in RECIPES.values())
    return Stage(tuple(RECIPES), parsed, load_seconds=1.0, parse_seconds=0.5)


def measured(runs=1, variants=VARIANTS):
    reports = []
    model = ScriptedModel({"boil": BOIL, "fry": FRY, "melt": MELT, "put": "put(egg, bowl)"})
    rows = measure(stage(), model, load_primitives("recipe"), OneLinersFail(), runs, variants, 7, reports.append,
                   lambda _: None)
    return rows, reports, model


def test_each_variant_counts_calls_as_the_paper_defines_it():
    rows, _, model = measured()
    by_variant = {row["variant"]: row for row in rows}
    assert [row["variant"] for row in rows] == list(VARIANTS)
    # AR+A: boil egg, fry, melt reduced; put a primitive; boil potato from the library.
    assert by_variant["AR+A"]["llm_calls"] == 3 and by_variant["AR+A"]["library_hits"] == 1
    # Warm: all from the library, fry too (its entry records that the model wrote no plan): no call at all.
    warm = by_variant["AR+A warm"]
    assert (warm["llm_calls"], warm["library_hits"], warm["no_plan_hits"]) == (0, 4, 1)
    assert by_variant["AR"]["llm_calls"] == 4 and by_variant["AR*"]["llm_calls"] == 5
    assert model.calls == sum(row["llm_calls"] + row["repair_calls"] for row in rows)
    assert {row["actions"] for row in rows} == {5}


def test_validated_rate_approved_only_and_repairs():
    rows, _, _ = measured()
    by_variant = {row["variant"]: row for row in rows}
    cold = by_variant["AR+A"]
    # boil passed, melt refused (one line), fry had no plan to check; nothing was repaired.
    assert cold["new_reductions"] == 3 and cold["validated"] == 1 and cold["checked"] == 2
    assert cold["validated_rate"] == pytest.approx(1 / 3) and cold["repair_calls"] == 0
    assert cold["check_seconds"] == pytest.approx(0.5)
    assert cold["wall_seconds"] == pytest.approx(cold["seconds"] - 0.5 + 0.5, abs=1e-3)  # checks out, parse in
    # Only boil was approved: melt's pending entry is skipped, so melt and fry go to the model.
    approved = by_variant["AR+A approved-only"]
    assert approved["llm_calls"] == 2 and approved["library_hits"] == 2
    # From an empty library with repairs: melt fails, is written again twice and still fails.
    repair = by_variant["AR+A repair"]
    assert repair["llm_calls"] == 3 and repair["repair_calls"] == 2 and repair["validated"] == 1


def test_executability_is_admissible_plan_actions_over_all_generated():
    rows, _, _ = measured(variants=("AR",))
    # boil egg 2 + put 1 + boil potato 2 + melt 1 admissible; fry: 2 dropped lines and no plan.
    assert rows[0]["admissible"] == 6 and rows[0]["inadmissible"] == 3
    assert rows[0]["executability"] == pytest.approx(6 / 9)
    # The pipeline's rate counts the model's lines only: 5 of 7.
    assert rows[0]["line_executability"] == pytest.approx(5 / 7)


def test_runs_take_their_own_seed_and_library_and_report_after_every_recipe():
    rows, reports, _ = measured(runs=2, variants=("AR+A",))
    assert [(row["seed"], row["llm_calls"]) for row in rows] == [(7, 3), (8, 3)]
    partial = [report[-1]["recipes_done"] for report in reports]
    assert partial == [1, 2, 2, 1, 2, 2]  # each recipe as it finishes, then the finished row
    assert [(r["recipe"], r["actions"], r["llm_calls"]) for r in rows[0]["per_recipe"]] == [("1", 2, 1), ("2", 3, 2)]


def test_the_first_seed_keeps_the_files_order_and_later_seeds_shuffle_it():
    numbers = tuple(str(n) for n in range(20))
    twenty = Stage(numbers, tuple(f"recipe {n}" for n in numbers), load_seconds=0.0, parse_seconds=0.0)
    assert in_run_order(twenty, FIRST_SEED) == twenty
    shuffled = [in_run_order(twenty, FIRST_SEED + k) for k in (1, 2)]
    assert all(sorted(s.numbers, key=int) == list(numbers) and s.numbers != numbers for s in shuffled)
    assert shuffled[0].numbers != shuffled[1].numbers and in_run_order(twenty, FIRST_SEED + 1) == shuffled[0]
    assert all(s.recipes == tuple(f"recipe {n}" for n in s.numbers) for s in shuffled)  # pairs kept together


def test_the_markdown_has_mean_and_std_beside_the_paper_and_marks_unfinished_runs():
    rows, _, _ = measured(runs=2)
    running = dict(next(row for row in rows if row["variant"] == "AR*"), seed=9, recipes_done=1, llm_calls=1)
    table = table1_markdown(rows + [running], total=2)
    lines = table.splitlines()
    assert lines[0].startswith("| variant | model | runs | executability | validated rate | LLM calls")
    ar_star = next(line for line in lines if line.startswith("| AR* "))
    assert "| 2 (+1 partial) |" in ar_star and "| 5 ± 0 |" in ar_star and "0.91 · 275 · 14.85" in ar_star
    repair = next(line for line in lines if line.startswith("| AR+𝔸 with repairs"))
    assert "| 0.33 ± 0.00 | 3 ± 0 (+ 2 ± 0) |" in repair  # validated rate, calls and repair calls
    assert "scripted: AR+𝔸 makes 0.60 × the calls of AR*, 0.75 × AR" in table
    only_partial = table1_markdown([dict(rows[-1], recipes_done=1)], total=2)
    assert "| partial: 1 of 2 recipes |" in only_partial
    # AR* cut short after the first recipe: compared with AR+A over that recipe only (1 call against 2).
    cut = [r for r in rows if r["variant"] == "AR+A"] + [dict(next(r for r in rows if r["variant"] == "AR*"),
                                                             recipes_done=1)]
    assert "AR+𝔸 makes 0.50 × the calls of AR* over the first 1 recipes (paper" in table1_markdown(cut, total=2)


def test_a_warm_rerun_needs_its_cold_run():
    with pytest.raises(UserError, match="reuse the library"):
        check_variants(("AR+A warm", "AR"))
    with pytest.raises(UserError, match="unknown variant"):
        check_variants(("AR+B",))


def test_mean_std_and_written_files(tmp_path):
    assert mean_std([1.0, 3.0]) == (2.0, pytest.approx(1.4142, abs=1e-4))
    assert pm([5.0]) == "5.00 ± 0.00"
    json_path, md_path = write(tmp_path / "out", "demo", {"value": 1}, "| a |\n")
    record = json.loads(json_path.read_text())
    assert record["benchmark"] == "demo" and record["value"] == 1 and record["machine"]["cpus"] >= 1
    assert md_path.read_text().splitlines()[1] == "| a |" and "CPUs at nice" in md_path.read_text()
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["demo.json", "demo.md"]


def test_table2_side_by_side():
    run = {"plan": [], "sources": [], "llm_calls": 0, "plan_seconds": 1.0, "rollout_seconds": 0.5, "actions": 3}
    record = {"model": "m", "runs": 2, "tasks": ["cut-bread"], "variants": {
        "AR": {"runs": 2, "tasks": {"cut-bread": [dict(run, success=True), dict(run, success=False)]}},
        "AR+A": {"runs": 2, "tasks": {"cut-bread": [dict(run, success=True), dict(run, success=True)]}}}}
    table = table2_markdown(record).splitlines()
    assert table[2] == "| cut-bread | 1/2 | 1.50 ± 0.00 | 2/2 | 1.50 ± 0.00 | — | — | — | — | 9/10 · 12.85 | 8/10 · 1.12 |"
    assert "- AR, all tasks: success 1/2 (50 %); seconds per rollout 1.50 (first run 1.50, later runs 1.50)" in table


def test_table2_task_sets():
    chosen = {which: [t.id for t in choose_tasks(which)] for which in TASK_SETS}
    assert chosen["paper"] == ["microwave-potato", "chop-tomato", "cut-bread", "refrigerate-apple"]
    assert chosen["all"] == chosen["paper"] + chosen["suite"] and len(chosen["all"]) == 33  # tasks.toml only
    assert len(chosen["paraphrase"]) == 15 and all(i.startswith("para-") for i in chosen["paraphrase"])
    assert chosen["smoke"] == ["microwave-potato"]
    with pytest.raises(UserError, match="unknown task set"):
        choose_tasks("held-out")


def test_the_library_bound_counts_distinct_keys_of_reduced_actions():
    # put is passed through; boil (what) twice, fry and melt once each.
    assert library_bound(stage(), load_primitives("recipe")) == {
        "actions": 5, "primitive": 1, "reduced_by_ar": 4, "distinct_keys": 3, "distinct_verbs": 3}


def test_the_bound_is_stated_under_the_table():
    rows, _, _ = measured(variants=("AR+A", "AR*"))
    table = table1_markdown(rows, 2, library_bound(stage(), load_primitives("recipe")))
    # the bound holds for exact keys; reuse across verbs and signatures (on by default) can go below it
    assert "with exact keys alone AR+𝔸 needs at least 3 calls: 0.75 × AR, 0.60 × AR*." in table
    assert "across signatures (the default; `translate --exact-keys` turns it off) can go below it" in table
    assert all(row["cross_reuses"] == 0 for row in rows)  # counted in every row (no two verbs share a row here)
    assert all("cross_reuses" in recipe for row in rows for recipe in row["per_recipe"])


def test_refused_plans_are_counted_by_kind_with_their_objects_left_out():
    from cook2ltl.bench.refusals import problem_kind

    holds = "the agent holds nothing; the plan must pick up {} first"
    kinds = {problem_kind(LineProblem(1, f"put({food}, pot)", holds.format(food))) for food in ("meat", "mix_rhubarb")}
    assert kinds == {"put: the agent holds nothing; the plan must pick up … first"}
    assert problem_kind(LineProblem(4, "wait(ribs == cooked)", "goal state not reached: ribs never became cooked")) \
        == "wait: goal state not reached: … never became …"
    rows, _, _ = measured(variants=("AR+A", "AR+A repair"))
    cold = next(row for row in rows if row["variant"] == "AR+A")
    assert cold["refusals"] == {"turn_on: too short": 1}  # melt's one-line plan; fry had no plan to check
    table = table1_markdown(rows, total=2)
    assert "AR+𝔸 (library from empty), scripted, plans refused by the kitchen (1), by first problem: " \
           "turn_on: too short (1)." in table


def test_the_world_variant_reports_effects_reached_and_the_planners_lines():
    rows, _, _ = measured(variants=("AR+A world",))
    (row,) = rows
    # boil egg, fry onion, melt butter are new; the planner completes each to its effect (the fake model's
    # fry has no admissible line, so the planner writes the whole plan).
    assert row["world_new"] == 3 and row["world_reached"] == 3 and row["world_no_effect"] == 0
    assert row["world_planner_lines"] > 0 and row["world_as_written"] < 3
    assert "AR+𝔸 in the world model: 1.00" in table1_markdown(rows, 2)
