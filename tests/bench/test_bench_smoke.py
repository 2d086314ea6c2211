"""`cook2ltl bench all --smoke`: every benchmark runs end to end on a sliver of its work, with the real models.

Benchmarks are not tests; this only checks that they still run and write results of the right shape.
"""

import json
import os
import subprocess
import sys
from pathlib import Path

from tests.models_required import require_models

BENCHMARKS = ("table1", "table2", "ner", "micro", "reduce", "fuzz")


def test_bench_smoke_writes_every_result(tmp_path):
    require_models("smollm2-135m", "gliner-cook2ltl", "spacy-sm")
    out = tmp_path / "results"
    command = [str(Path(sys.executable).with_name("cook2ltl")), "bench", "all", "--smoke", "--out", str(out)]
    done = subprocess.run(command, capture_output=True, text=True, timeout=300,
                          env={**os.environ, "HF_HUB_OFFLINE": "1"})
    assert done.returncode == 0, done.stderr[-2000:]
    assert sorted(p.name for p in out.iterdir()) == sorted(f"{b}.{ext}" for b in BENCHMARKS for ext in ("json", "md"))
    results = {name: json.loads((out / f"{name}.json").read_text()) for name in BENCHMARKS}
    for name, record in results.items():
        assert record["benchmark"] == name and "--smoke" in record["command"] and record["machine"]["cpus"] >= 1
        assert (out / f"{name}.md").read_text().count("\n|") >= 2  # a header and at least one row

    rows = {row["variant"]: row for row in results["table1"]["runs"]}
    assert list(rows) == ["AR+A", "AR+A warm", "AR*"] and results["table1"]["model"] == "smollm2-135m"
    assert rows["AR+A warm"]["llm_calls"] == 0 < rows["AR+A"]["llm_calls"] <= rows["AR*"]["llm_calls"]
    assert {row["actions"] for row in rows.values()} == {rows["AR*"]["llm_calls"]}  # AR* reduces every action
    for row in rows.values():
        assert 0 <= row["executability"] <= 1 and row["recipes_done"] == 1 and row["wall_seconds"] > 0
    assert rows["AR+A"]["validated_rate"] is not None and 0 <= rows["AR+A"]["validated_rate"] <= 1

    table2 = results["table2"]["variants"]
    assert set(table2) == {"AR", "AR+A", "AR+A repair", "AR+A world"}
    for variant in table2.values():
        [(task, runs)] = variant["tasks"].items()
        assert task == "microwave-potato" and len(runs) == 1 and isinstance(runs[0]["success"], bool)
        assert runs[0]["plan_seconds"] > 0

    ner = results["ner"]["models"]
    assert ner["gliner"]["overall"]["f1"] > 0.5  # the trained span model, on 20 held-out sentences
    assert 0 <= ner["spacy"]["overall"]["f1"] <= 1 and set(ner["spacy"]) >= {"VERB", "WHAT", "TEMP"}

    micro = results["micro"]
    assert micro["span_model"]["ms_per_sentence"] > 0 and micro["language_model"]["seconds_per_reduction"] > 0
    assert 0 < micro["ltl"]["progress_ms_per_step_cold"]["median"] < 50
    assert micro["kitchen"]["actions"] > 0 and micro["kitchen"]["seconds_per_action"] > 0
    assert "first_screen_seconds" in micro["app"] or "error" in micro["app"]
    shares = micro["translation"]["shares"]  # where a cold translation's time went; no second counted twice
    assert set(shares) == {"model", "kitchen", "world model", "parsing", "rest"} and min(shares.values()) >= 0
    assert micro["translation"]["parts_seconds"]["model"] > 0 and micro["translation"]["llm_calls"] > 0

    reduce = results["reduce"]  # two ai2thor actions reduced by smollm2: one cold, one warm
    [row] = reduce["rows"]
    assert row["model"] == "smollm2-135m" and row["comments"] is False and reduce["tasks"] == len(row["plans"]) == 2
    assert row["cold_seconds_mean"] > 0 and row["warm_seconds_median"] > 0 and 0 <= row["key_calls_found_share"] <= 1

    fuzz = results["fuzz"]  # every boundary's target, 20 examples each: no traceback, hang or loss
    assert fuzz["failed"] == [] and fuzz["passed"] > 0 and fuzz["tried"] and min(fuzz["tried"].values()) > 0
