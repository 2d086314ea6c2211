"""bench micro's batch speed-up and the demo recipe in the app: their rows from a record, and the two steps run
with the smallest model (smollm2-135m) on two reductions and two sentences."""

from cook2ltl.bench.micro import app_demo, batch_decoding, micro_markdown
from tests.models_required import require_models

SMOKE_MODEL = "smollm2-135m"
BATCH = {"model": "m", "reductions": 8, "lanes": 4, "alone_seconds": 22.7, "batched_seconds": 13.4,
         "speedup": 22.7 / 13.4, "alone_cpu_seconds": 40.0, "batched_cpu_seconds": 25.0, "identical_plans": 7}
APP_DEMO = {"model": "m", "seconds": 58.2, "first_screen_seconds": 0.61, "formulas_shown": 15, "steps": 15,
            "actions": 21, "llm_calls": 9, "repair_calls": 1}


def test_the_two_rows_render_from_a_record():
    lines = micro_markdown({"batch": BATCH, "app_demo": APP_DEMO}).splitlines()
    assert lines[:2] == ["| what | speed | notes |", "|---|---|---|"] and len(lines) == 4
    assert lines[2] == ("| batch decoding (m) | 1.69x: 22.7 s alone, 13.4 s batched | 8 reductions, 4 lanes; "
                        "7 of 8 plans identical |")
    assert lines[3].startswith("| the demo recipe in the app, cold (empty library) (m) | 58.2 s to every formula "
                               "shown | first screen 0.61 s; 15 formulas of 15 steps, 9 model calls + 1 repairs "
                               "for 21 actions")


def test_a_failed_app_run_is_a_row_that_says_why():
    [row] = micro_markdown({"app_demo": {"model": "m", "error": "no translation within 1020 s"}}).splitlines()[2:]
    assert row == ("| the demo recipe in the app, cold (empty library) (m) | not measured | "
                   "no translation within 1020 s |")


def test_the_smoke_steps_return_their_fields():
    require_models(SMOKE_MODEL, "gliner-cook2ltl", "spacy-sm")
    batch = batch_decoding(SMOKE_MODEL, 2, 2)
    assert batch.keys() == BATCH.keys() and batch["reductions"] == batch["lanes"] == 2
    assert batch["alone_seconds"] > 0 and batch["batched_seconds"] > 0 and 0 <= batch["identical_plans"] <= 2
    demo = app_demo(SMOKE_MODEL, "Preheat the oven to 375 F. Bring a large pot of salted water to a boil.", 240)
    assert "error" not in demo, demo["error"]
    assert demo.keys() == APP_DEMO.keys() and demo["formulas_shown"] == demo["steps"] == 2
    assert 0 < demo["first_screen_seconds"] < demo["seconds"] and demo["llm_calls"] > 0
