"""`cook2ltl translate` with the kitchen check: on by default for AR+A, the rates printed and in --json."""

import json

import pytest
from typer.testing import CliRunner

from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel

TEXT = "Microwave the potato. Chop the tomato."
SPANS = {
    "Microwave the potato.": [("VERB", "Microwave"), ("WHAT", "the potato")],
    "Chop the tomato.": [("VERB", "Chop"), ("WHAT", "the tomato")],
}
ANSWERS = {
    "microwave": ["open(microwave)\nput(potato, microwave)\nclose(microwave)\nturn_on(microwave)",
                  "open(microwave)\npick_up(potato)\nput(potato, microwave)\nclose(microwave)\nturn_on(microwave)"],
    "chop": "slice(tomato)",  # never holds a knife
}


@pytest.fixture
def cli(monkeypatch, tmp_path):
    pytest.importorskip("ai2thor")
    import cook2ltl.assembly.backends
    from cook2ltl.cli import app

    monkeypatch.setattr(cook2ltl.assembly.backends, "span_extractor", lambda settings: ScriptedSpans(SPANS))
    monkeypatch.setattr(cook2ltl.assembly.backends, "dependency_parser", lambda: ScriptedDependencies())
    monkeypatch.setattr(cook2ltl.assembly.backends, "load_model", lambda name: ScriptedModel(ANSWERS))
    monkeypatch.setenv("COOK2LTL_CONFIG", str(tmp_path / "none.toml"))
    monkeypatch.setenv("HOME", str(tmp_path))
    monkeypatch.setenv("COOK2LTL_KITCHEN_CACHE", str(tmp_path / "cache"))
    recipe = tmp_path / "recipe.txt"
    recipe.write_text(TEXT)
    runner = CliRunner()

    def invoke(*args, library="library.sqlite"):
        # the kitchen check and its repairs, as they run without the world model (tests/world has it)
        result = runner.invoke(app, ["translate", str(recipe), "--primitives", "ai2thor", "--no-ground",
                                     "--library", str(tmp_path / library), *args])
        assert result.exit_code == 0, result.output
        return result

    return invoke


def test_validation_is_on_by_default_and_the_rates_are_printed(cli):
    shown = cli().output
    assert "kitchen check: passed (FloorPlan1, after 1 repair)" in shown
    assert "kitchen check: failed" in shown and "! line 1 slice(tomato): Slicing needs" in shown
    assert "executability 100% (12 of 12 lines the model wrote are admissible)" in shown
    assert ("validated 50% (1 of 2 new reductions run in the kitchen, 1 after repair; 3 repair calls; "
            "2 checked)") in shown


def test_json_has_the_rates_and_each_check(cli):
    data = json.loads(cli("--json", "--repairs", "0").stdout)
    stats = data["stats"]
    assert stats["validated_rate"] == 0.0 and stats["executability"] == 1.0 and stats["repair_calls"] == 0
    assert (stats["checked"], stats["validated"], stats["written_lines"]) == (2, 0, 5)
    microwave = data["steps"][0]["actions"][0]
    assert microwave["validation"]["status"] == "failed" and microwave["repairs"] == []
    assert microwave["validation"]["problems"][0].startswith("line 2 put(potato, microwave)")


def test_without_validation(cli):
    shown = cli("--no-validate").output
    assert "kitchen check" not in shown and "validated - (not validating)" in shown
    data = json.loads(cli("--no-validate", "--json", library="other.sqlite").stdout)
    assert data["stats"]["validated_rate"] is None and data["steps"][0]["actions"][0]["validation"] is None


def test_approved_only_reduces_pending_actions_again(cli):
    cli("--repairs", "0")
    again = json.loads(cli("--json", "--approved-only", "--repairs", "0").stdout)
    assert again["stats"]["library_hits"] == 0 and again["stats"]["llm_calls"] == 2
    reused = json.loads(cli("--json", "--repairs", "0").stdout)
    assert reused["stats"]["library_hits"] == 2 and reused["stats"]["llm_calls"] == 0


def test_a_reused_entry_that_failed_is_shown(cli):
    cli("--repairs", "0")
    shown = cli("--repairs", "0").output
    assert shown.count("kitchen check when learnt: failed") == 2 and "! line 1 slice(tomato)" in shown
