"""The core stays fast to import: heavy backends load only when a model is first used, and the core is
reachable without the app (no Textual, no cook2ltl.ui); an import left inside a function says why."""

import ast
import io
import json
import shutil
import subprocess
import sys
import tokenize
from pathlib import Path

import pytest

HEAVY = ["torch", "gliner", "spacy", "transformers", "llama_cpp", "ai2thor", "textual"]
ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "app" / "cook2ltl"


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
        pytest.fail("lint-imports is not installed: install the dev extra (pip install -e '.[dev]'), which has "
                    "import-linter; the layers contract must be checked, not skipped")
    result = subprocess.run([lint], cwd=ROOT, capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "0 broken" in result.stdout


def _is_type_checking(node: ast.AST) -> bool:
    test = getattr(node, "test", None)
    return isinstance(node, ast.If) and (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING"
                                         or isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _deferred_runs(tree: ast.AST) -> list[list[ast.stmt]]:
    """The imports inside functions (not under `if TYPE_CHECKING:`), in runs: the import statements that follow
    one another in the same block (blank lines between them allowed)."""
    runs: list[list[ast.stmt]] = []

    def visit(node: ast.AST, in_function: bool) -> None:
        for block in ("body", "orelse", "finalbody", "handlers"):
            if block == "body" and _is_type_checking(node):
                continue  # names for annotations only: nothing imports them at run time
            statements = getattr(node, block, None)
            if not isinstance(statements, list):
                continue
            run: list[ast.stmt] = []
            for statement in statements:
                if isinstance(statement, (ast.Import, ast.ImportFrom)):
                    if in_function and not run:
                        runs.append(run)
                    run.append(statement)
                    continue
                run = []
                visit(statement, in_function or isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef)))
        for case in getattr(node, "cases", ()):  # match statements
            visit(case, in_function)

    visit(tree, False)
    return runs


def _unexplained(path: Path) -> list[int]:
    """Lines of deferred imports with no comment on their own lines nor on a comment line directly above them
    or above an import before them in their run."""
    source = path.read_text(encoding="utf-8")
    lines = source.splitlines()
    commented = {token.start[0] for token in tokenize.generate_tokens(io.StringIO(source).readline)
                 if token.type == tokenize.COMMENT}
    offenders = []
    for run in _deferred_runs(ast.parse(source)):
        said = False  # a comment line above this import or an earlier one of the run covers it
        for statement in run:
            said = said or statement.lineno >= 2 and lines[statement.lineno - 2].lstrip().startswith("#")
            if not (said or commented & set(range(statement.lineno, statement.end_lineno + 1))):
                offenders.append(statement.lineno)
    return offenders


def test_every_deferred_import_says_why():
    """An import inside a function is deferred on purpose (a heavy or optional library, start-up time a test
    here guards, a rarely used slow path) and says so: a comment on its line, or one line directly above the
    run of imports it belongs to. One that needs no reason belongs at the top of its module."""
    offenders = [f"{path.relative_to(ROOT)}:{line}" for path in sorted(PACKAGE.rglob("*.py"))
                 for line in _unexplained(path)]
    assert not offenders, ("imports inside functions without a reason (say why in a comment on the import or "
                           "just above its run of imports, or move them to the top of the module):\n"
                           + "\n".join(offenders))
