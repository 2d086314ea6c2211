"""`cook2ltl models` and `cook2ltl doctor` on the provisioned stack."""

import subprocess
import sys

from cook2ltl.assembly.manifest import load_manifest


def cook2ltl(*arguments: str, **options) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "cook2ltl", *arguments], capture_output=True, text=True,
                          timeout=600, env=options.get("env"))


def test_models_lists_every_model_as_ready():
    result = cook2ltl("models")
    assert result.returncode == 0, result.stderr
    for name in load_manifest():
        assert name in result.stdout
    assert result.stdout.count(" ready ") == len(load_manifest())
    assert "missing" not in result.stdout and "corrupt" not in result.stdout


def test_doctor_runs_every_model_once_and_passes():
    result = cook2ltl("doctor")
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout.count("✓ smoke") == len(load_manifest())


def test_doctor_names_the_fix_for_a_missing_model(tmp_path):
    import os

    env = {**os.environ, "COOK2LTL_MODEL_CACHE": str(tmp_path / "empty-cache")}
    result = cook2ltl("doctor", env=env)
    assert result.returncode == 1
    assert "missing" in result.stdout and "fix: make models" in result.stdout


def test_eval_ner_reports_strict_f1_per_label():
    import json

    result = cook2ltl("models", "eval-ner", "--json")
    assert result.returncode == 0, result.stderr
    scores = json.loads(result.stdout)
    assert set(scores) == {"overall", "VERB", "WHAT", "WHERE", "HOW", "TIME", "TEMP", "sentences"}
    # Far above chance: an untrained head finds nothing (F1 0).
    assert scores["overall"]["f1"] > 0.5 and scores["sentences"] > 100
