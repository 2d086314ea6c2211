"""AR+𝔸 reusing an entry across verbs the verb-effect table reads as one action and across signatures
(library.reuse), with fake parsers, a scripted model and a real library: what is reused, why, and when not."""

import json

import pytest
from typer.testing import CliRunner

from cook2ltl.domain.actions import Source
from cook2ltl.library import Library
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline.records import TranslationFinished
from cook2ltl.pipeline.serialize import translation_json
from cook2ltl.pipeline.translator import Translator, translate
from cook2ltl.reduce.primitives import load_primitives
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel

PRIMITIVES = load_primitives("recipe")
STIR = "pick_up(spoon)\nstir($what)"  # a lab's stir entry (stir itself is a primitive of the recipe set)
SPANS = {
    "Stir in the sugar.": [("VERB", "Stir in"), ("WHAT", "the sugar")],
    "Add the egg to the bowl.": [("VERB", "Add"), ("WHAT", "the egg"), ("WHERE", "to the bowl")],
    "Add the flour, the sugar and the salt to the bowl.": [
        ("VERB", "Add"), ("WHAT", "the flour"), ("WHAT", "the sugar"), ("WHAT", "the salt"), ("WHERE", "to the bowl")],
    "Add the flour and the sugar to the bowl slowly.": [
        ("VERB", "Add"), ("WHAT", "the flour"), ("WHAT", "the sugar"), ("WHERE", "to the bowl"), ("HOW", "slowly")],
    "Chill the cream until cold.": [("VERB", "Chill"), ("WHAT", "the cream"), ("TIME", "until cold")],
    "Chill the milk.": [("VERB", "Chill"), ("WHAT", "the milk")],
    "Boil the egg.": [("VERB", "Boil"), ("WHAT", "the egg")],
    "Simmer the potato.": [("VERB", "Simmer"), ("WHAT", "the potato")],
}
ADD = "pick_up(egg)\nput(egg, bowl)"


@pytest.fixture
def library(tmp_path):
    opened = Library(tmp_path / "library.sqlite")
    yield opened
    opened.close()


def translated(text, model, library, **options):
    parsed = parse_recipe(text, ScriptedSpans(SPANS), ScriptedDependencies())
    translator = Translator(PRIMITIVES, model, library, **options)
    return next(e.translation for e in translate(parsed, translator) if isinstance(e, TranslationFinished))


def results(translation):
    return [result for step in translation.steps for result in step.actions]


def lines(result):
    return [call.text() for call in result.plan]


def test_stir_in_reuses_the_entry_of_stir_and_says_why(library):
    stir = library.add("recipe", "stir", ("what",), STIR, "lab", "")
    model = ScriptedModel({})
    translation = translated("Stir in the sugar.", model, library)
    [result] = results(translation)
    assert model.calls == 0 and result.reduction.source == Source.LIBRARY and result.reduction.entry_id == stir.id
    assert lines(result) == ["pick_up(spoon)", "stir(sugar)"]
    assert (result.reuse.entry_id, result.reuse.verb, result.reuse.signature) == (stir.id, "stir", ("what",))
    assert result.reuse.reasons == ("the verb-effect table reads stir_in as stir",)
    assert (translation.stats.library_hits, translation.stats.cross_reuses, translation.stats.new_entries) == (1, 1, 0)
    assert [e.verb for e in library.entries()] == ["stir"]  # nothing learnt under stir_in: no model call was made


def test_three_whats_reuse_a_one_what_entry_distributed(library):
    model = ScriptedModel({"add": ADD})
    translation = translated("Add the egg to the bowl. Add the flour, the sugar and the salt to the bowl.", model,
                             library)
    learnt, reused = results(translation)
    assert model.calls == 1 and reused.reduction.source == Source.LIBRARY
    assert lines(reused) == ["pick_up(flour)", "put(flour, bowl)", "pick_up(sugar)", "put(sugar, bowl)",
                             "pick_up(salt)", "put(salt, bowl)"]
    assert reused.reuse.entry_id == learnt.reduction.entry_id
    assert reused.reuse.reasons == ("distributed over 3 objects: flour, sugar, salt",)
    assert [(e.verb, e.signature) for e in library.entries()] == [("add", ("what", "where"))]


def test_an_argument_the_body_does_not_use_is_ignored_and_said(library):
    translated("Add the egg to the bowl.", ScriptedModel({"add": ADD}), library)
    translation = translated("Add the flour and the sugar to the bowl slowly.", ScriptedModel({}), library)
    [result] = results(translation)
    assert result.reuse.reasons == ("distributed over 2 objects: flour, sugar", "ignores how: slowly")


def test_an_entry_whose_body_needs_a_time_is_not_reused_without_one(library):
    model = ScriptedModel({"chill": ["put(cream, fridge)\nwait(cream == cold)", "put(milk, fridge)"]})
    translation = translated("Chill the cream until cold. Chill the milk.", model, library)
    assert library.entries()[0].body == "put($what, fridge)\nwait($what == $time)"
    assert model.calls == 2 and [r.reduction.source for r in results(translation)] == [Source.LLM, Source.LLM]
    assert translation.stats.cross_reuses == 0


def test_a_verb_with_its_own_row_does_not_reuse_another_verbs_entry(library):
    model = ScriptedModel({"boil": "pick_up(egg)\nput(egg, pot)", "simmer": "put(potato, pot)"})
    translation = translated("Boil the egg. Simmer the potato.", model, library)
    assert model.calls == 2 and results(translation)[1].reuse is None  # simmer has a row: not read as boil


def test_lab_mode_reuses_approved_entries_only(library):
    stir = library.add("recipe", "stir", ("what",), STIR, "lab", "")
    model = ScriptedModel({"stir_in": "stir(sugar)"})
    pending = translated("Stir in the sugar.", model, library, approved_only=True)
    assert model.calls == 1 and results(pending)[0].reuse is None
    library.set_status(stir.id, "approved", by="tester")
    library.set_status(library.lookup("recipe", "stir_in", ("what",)).id, "rejected", by="tester")
    approved = translated("Stir in the sugar.", model, library, approved_only=True)
    assert model.calls == 1 and results(approved)[0].reuse.entry_id == stir.id


def test_exact_keys_only_when_turned_off(library):
    library.add("recipe", "stir", ("what",), STIR, "lab", "")
    model = ScriptedModel({"stir_in": "stir(sugar)"})
    translation = translated("Stir in the sugar.", model, library, reuse=False)
    assert model.calls == 1 and results(translation)[0].reuse is None and translation.stats.cross_reuses == 0
    # now the exact key has its own entry, which wins over the reuse when it is back on
    again = translated("Stir in the sugar.", ScriptedModel({}), library)
    [result] = results(again)
    assert result.reuse is None and result.reduction.entry_id == library.lookup("recipe", "stir_in", ("what",)).id


def test_the_json_carries_the_reuse(library):
    stir = library.add("recipe", "stir", ("what",), STIR, "lab", "")
    data = json.loads(json.dumps(translation_json(translated("Stir in the sugar.", ScriptedModel({}), library))))
    [action] = data["steps"][0]["actions"]
    assert action["source"] == "library" and action["library_entry"] == stir.id
    assert action["reused"] == {"entry": stir.id, "verb": "stir", "signature": ["what"],
                                "reasons": ["the verb-effect table reads stir_in as stir"]}
    assert data["stats"]["cross_reuses"] == 1


def test_the_translate_command_shows_reuse_and_turns_it_off(monkeypatch, tmp_path):
    import cook2ltl.assembly.backends
    from cook2ltl.cli import app

    monkeypatch.setattr(cook2ltl.assembly.backends, "span_extractor", lambda settings: ScriptedSpans(SPANS))
    monkeypatch.setattr(cook2ltl.assembly.backends, "dependency_parser", lambda: ScriptedDependencies())
    monkeypatch.setattr(cook2ltl.assembly.backends, "load_model", lambda name: ScriptedModel({"add": ADD}))
    monkeypatch.setenv("COOK2LTL_CONFIG", str(tmp_path / "none.toml"))
    recipe = tmp_path / "recipe.txt"
    recipe.write_text("Add the egg to the bowl. Add the flour, the sugar and the salt to the bowl.")
    runner = CliRunner()

    def run(library, *args):
        result = runner.invoke(app, ["translate", str(recipe), "--no-ground", "--no-validate", "--library",
                                     str(tmp_path / library), *args])
        assert result.exit_code == 0, result.output
        return result.stdout

    shown = " ".join(run("shown.sqlite").split())  # the counts' line is wrapped to the terminal
    assert ("→ add(flour, sugar, salt, bowl) library #1 reused: entry 1 add(what, where): distributed over 3 "
            "objects: flour, sugar, salt pick_up(flour)") in shown
    assert "1 from the library (1 reused across verbs or signatures), 1 LLM calls" in shown
    on = json.loads(run("on.sqlite", "--json"))
    assert on["stats"]["llm_calls"] == 1 and on["steps"][1]["actions"][0]["reused"]["entry"] == 1
    off = json.loads(run("off.sqlite", "--json", "--exact-keys"))
    assert off["stats"]["llm_calls"] == 2 and off["steps"][1]["actions"][0]["reused"] is None
    assert off["stats"]["cross_reuses"] == 0 and off["steps"][0]["actions"][0]["reused"] is None


def test_in_the_world_model_a_reuse_that_falls_short_is_completed(library):
    from cook2ltl.world.kitchens import grounding

    library.add("recipe", "add", ("what", "where"), "remove($what, countertop)\nstir($where)", "lab", "")
    model = ScriptedModel({})
    translation = translated("Add the flour, the sugar and the salt to the bowl.", model, library,
                             grounding=grounding(PRIMITIVES))
    [result] = results(translation)
    assert model.calls == 0 and result.reuse.reasons == ("distributed over 3 objects: flour, sugar, salt",)
    check = result.check  # checked where the recipe has got to: the second pick-up finds the hand full
    assert check.json()["effect"] == ["in(flour, bowl)", "in(sugar, bowl)", "in(salt, bowl)"]
    assert check.effect_reached and check.planner_lines > 0 and check.json()["written_by"][0] == "library"
    for food in ("flour", "sugar", "salt"):  # into the bowl, or onto what is in it: the planner's shortest
        assert any(food in line for line in lines(result)[1:])
