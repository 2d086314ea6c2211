"""The ``ltl parse`` and ``ltl progress`` commands."""

import json

import typer
from typer.testing import CliRunner

from cook2ltl.errors import UserError
from cook2ltl.ltl.cli import ltl_app

# Mounted as in the main CLI, so the commands are tried as `cook2ltl ltl …`.
app = typer.Typer()
app.add_typer(ltl_app, name="ltl")
runner = CliRunner()


def run(*args):
    return runner.invoke(app, ["ltl", *args])


def test_parse_prints_both_syntaxes_and_atoms():
    result = run("parse", 'F(pick_up(knife) & F "slice(tomato, knife)")')
    assert result.exit_code == 0
    assert "◇(pick_up(knife) ∧ ◇slice(tomato, knife))" in result.stdout
    assert 'F("pick_up(knife)" & F"slice(tomato, knife)")' in result.stdout
    assert "pick_up(knife), slice(tomato, knife)" in result.stdout


def test_parse_json():
    result = run("parse", "G(a -> X[!] b)", "--json")
    assert result.exit_code == 0
    assert json.loads(result.stdout) == {
        "unicode": "□(a → ○[!]b)",
        "spot": "G(a -> X[!]b)",
        "atoms": ["a", "b"],
    }


def test_parse_error_shows_position():
    # UserError reaches the main CLI, which prints it and exits with 2.
    error = run("parse", "F(a &").exception
    assert isinstance(error, UserError)
    assert "line 1, column 6" in error.message
    assert "F(a &\n       ^" in error.message


def test_progress_table():
    result = run("progress", "F(a & F(stir U thickened))", "a", "-", "stir", "stir; thickened")
    assert result.exit_code == 0
    lines = result.stdout.splitlines()
    assert any("◇(stir 𝒰 thickened)" in line and "presumably false" in line for line in lines)
    assert "Trace as a whole: satisfied" in result.stdout


def test_progress_json():
    result = run("progress", "F(a & F b) & G !burnt", "a", "cold(apple); b", "--json")
    assert result.exit_code == 0
    payload = json.loads(result.stdout)
    assert payload["formula"] == "F(a & Fb) & G!burnt"
    assert payload["steps"] == [
        {
            "index": 1,
            "atoms": ["a"],
            "remaining": "Fb & G!burnt",
            "remaining_unicode": "◇b ∧ □¬burnt",
            "verdict": "presumably_false",
        },
        {
            "index": 2,
            "atoms": ["b", "cold(apple)"],
            "remaining": "G!burnt",
            "remaining_unicode": "□¬burnt",
            "verdict": "presumably_true",
        },
    ]
    assert payload["verdict"] == "presumably_true"


def test_progress_without_steps_judges_the_empty_trace():
    payload = json.loads(run("progress", "G a", "--json").stdout)
    assert payload == {"formula": "Ga", "steps": [], "verdict": "presumably_true"}


def test_progress_rejects_a_step_that_is_not_atoms():
    error = run("progress", "F a", "b", "a & b").exception
    assert isinstance(error, UserError)
    assert error.message == "step 2 is not a list of atoms: 'a & b' is not an atom"
    assert isinstance(run("progress", "F a", "a(").exception, UserError)
