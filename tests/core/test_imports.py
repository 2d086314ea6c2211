"""The core stays fast to import: heavy backends load only when a model is first used, and the core is
reachable without the app (no Textual, no cook2ltl.ui)."""

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

HEAVY = ["torch", "gliner", "spacy", "transformers", "llama_cpp", "ai2thor", "textual"]
ROOT = Path(__file__).resolve().parents[2]


def _imported(modules: str, watched: list[str]) -> list[str]:
    code = (
        "import sys, json\n"
        f"import {modules}\n"
        f"print(json.dumps([m for m in {watched!r} if m in sys.modules]))"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return json.loads(result.stdout)


def test_cli_and_core_import_no_model_library():
    assert _imported("cook2ltl.cli, cook2ltl.parse, cook2ltl.assembly.backends, cook2ltl.assembly.doctor, cook2ltl.assembly.provision",
                     HEAVY) == []


def test_the_command_line_loads_a_headless_command_only_when_it_runs():
    """`cook2ltl app` starts without the pipeline, the library or the LTL parser; `--help` still lists them all."""
    assert _imported("cook2ltl.cli", ["cook2ltl.pipeline.translator", "cook2ltl.library", "cook2ltl.ltl", "sqlite_utils",
                                      "cook2ltl.cli.translate_command", "cook2ltl.cli.bench_command"]) == []
    from typer.testing import CliRunner

    from cook2ltl.cli import COMMANDS, app

    listed = CliRunner().invoke(app, ["--help"], env={"COLUMNS": "200"})
    assert listed.exit_code == 0
    for name in [*COMMANDS, "app", "doctor"]:
        assert f"│ {name} " in listed.output
    assert "Translate a recipe into LTL formulas" in listed.output  # each command's own help, read from its module


def test_the_pipeline_library_and_kitchen_load_without_the_app():
    core = ("cook2ltl.pipeline.translator, cook2ltl.library, cook2ltl.assembly.trial, cook2ltl.assembly.planning, "
            "cook2ltl.pipeline.serialize, cook2ltl.ltl")
    assert _imported(core, ["textual", "cook2ltl.ui"]) == []


def test_the_app_starts_without_any_model_library():
    """Models load lazily, in a worker, when a run first needs them."""
    assert _imported("cook2ltl.ui.app, cook2ltl.ui.services", [m for m in HEAVY if m != "textual"]) == []


def test_the_import_contract_holds():
    """pyproject.toml's [tool.importlinter] contract: no core module reaches textual or cook2ltl.ui, even
    through another module."""
    lint = shutil.which("lint-imports", path=str(Path(sys.executable).parent))
    if lint is None:
        pytest.skip("import-linter is not installed (the dev extra)")
    result = subprocess.run([lint], cwd=ROOT, capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "0 broken" in result.stdout
