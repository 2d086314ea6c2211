"""`cook2ltl bench table1 --combine`: one Table I from the results of separate runs, without running anything."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from cook2ltl.bench.combine import combine_table1
from cook2ltl.errors import UserError


def run(variant: str, seed: int, recipes_done: int, calls: int) -> dict:
    return {"variant": variant, "model": "qwen", "seed": seed, "recipes_done": recipes_done, "executability": 1.0,
            "validated_rate": 0.5, "llm_calls": calls, "repair_calls": 0, "prompt_tokens": 10 * calls,
            "completion_tokens": calls, "wall_seconds": 60.0, "per_recipe": []}


def result(folder: Path, recipes: int, runs: list[dict], bound: dict | None = None) -> Path:
    """A table1.json as `cook2ltl bench table1` writes it, cut to what combining reads."""
    folder.mkdir()
    record = {"benchmark": "table1", "command": f"cook2ltl bench table1 --out {folder}", "machine": {"cpus": 2},
              "model": "qwen", "recipes": recipes, "runs": runs, **({"library_bound": bound} if bound else {})}
    (folder / "table1.json").write_text(json.dumps(record))
    return folder / "table1.json"


@pytest.fixture
def sources(tmp_path):
    bound = {"actions": 6, "primitive": 2, "reduced_by_ar": 4, "distinct_keys": 3, "distinct_verbs": 2}
    return [result(tmp_path / "arstar", 2, [run("AR*", 4242, 2, 6)]),
            result(tmp_path / "ar", 2, [run("AR", 4242, 2, 4), run("AR", 4243, 1, 2)], bound)]


def test_the_command_combines_the_finished_runs_into_one_table(tmp_path, sources):
    out = tmp_path / "combined"
    command = [str(Path(sys.executable).with_name("cook2ltl")), "bench", "table1", "--combine", str(sources[0]),
               "--combine", str(sources[1]), "--finished", "--out", str(out)]
    done = subprocess.run(command, capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr[-2000:]
    combined = json.loads((out / "table1.json").read_text())
    assert [(r["variant"], r["seed"]) for r in combined["runs"]] == [("AR*", 4242), ("AR", 4242)]  # not the partial
    assert [s["file"] for s in combined["sources"]] == [str(p) for p in sources] and combined["recipes"] == 2
    assert combined["library_bound"]["distinct_keys"] == 3 and "--combine" in combined["command"]
    table = (out / "table1.md").read_text()
    assert "| AR* (reduce every action) | qwen | 1 |" in table and "| AR (skip primitives) | qwen | 1 |" in table
    assert "at least 3 calls" in table and "| AR (skip primitives) |" in done.stderr  # the table is shown too


def test_without_finished_a_partial_run_is_kept_and_counted(tmp_path, sources):
    combined = combine_table1(sources, False, tmp_path / "out")
    assert len(combined["runs"]) == 3
    assert "| AR (skip primitives) | qwen | 1 (+1 partial) |" in (tmp_path / "out" / "table1.md").read_text()


def test_results_of_other_recipes_or_other_benchmarks_are_refused(tmp_path, sources):
    other = result(tmp_path / "ten", 10, [run("AR", 4242, 10, 20)])
    with pytest.raises(UserError, match=r"different numbers of recipes: \[2, 10\]"):
        combine_table1([sources[0], other], False, tmp_path / "out")
    (tmp_path / "micro.json").write_text(json.dumps({"benchmark": "micro", "runs": []}))
    with pytest.raises(UserError, match="is not a Table I result"):
        combine_table1([tmp_path / "micro.json"], False, tmp_path / "out")
    with pytest.raises(UserError, match="No Table I result at"):
        combine_table1([tmp_path / "nothing.json"], False, tmp_path / "out")


def test_combine_goes_with_table1_only(tmp_path, sources):
    command = [str(Path(sys.executable).with_name("cook2ltl")), "bench", "micro", "--combine", str(sources[0]),
               "--out", str(tmp_path / "out")]
    done = subprocess.run(command, capture_output=True, text=True, timeout=60)
    assert done.returncode == 2 and "--combine" in done.stderr and "Traceback" not in done.stderr
    assert not (tmp_path / "out").exists()  # refused before anything is made
