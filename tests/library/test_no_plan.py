"""A reduction with no admissible plan cached as an entry with an empty body: reused without the model, never a
callable verb, never approved, given a body by `library edit`, and carried by export and import."""

import json
import os
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from cook2ltl.domain.actions import Source
from cook2ltl.errors import UserError
from cook2ltl.library import Library, Status
from cook2ltl.library.exchange import export_library, import_library
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline.records import TranslationFinished
from cook2ltl.pipeline.translator import NO_PLAN_PROBLEM, Translator, translate
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.validation import Validation
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel

SPANS = {
    "Boil the egg.": [("VERB", "Boil"), ("WHAT", "the egg")],
    "Boil the potato and mash the potato.": [("VERB", "Boil"), ("WHAT", "the potato"), ("VERB", "mash"),
                                             ("WHAT", "the potato")],
}
TEXT = " ".join(SPANS)
NOTHING_ADMISSIBLE = {"boil": "fry(egg)\nexplode(egg)", "mash": "put(potato, bowl)\nboil(potato)\nstir(potato)"}
BOIL = "pick_up($what)\nput($what, pot)\nput(pot, stovetop)\nturn_on(stovetop)"


class PassingKitchen:
    """A kitchen check that passes every plan it is given, and keeps the actions it checked."""

    def __init__(self):
        self.checked = []

    def validate(self, action, plan, so_far=None):
        self.checked.append(action.verb)
        return Validation(True, (), "FloorPlan1", 0.1)

    def close(self):
        pass


@pytest.fixture
def library(tmp_path):
    opened = Library(tmp_path / "library.sqlite")
    yield opened
    opened.close()


def translated(model, library, validator=None, approved_only=False):
    recipe = parse_recipe(TEXT, ScriptedSpans(SPANS), ScriptedDependencies())
    translator = Translator(load_primitives("recipe"), model, library, validator=validator,
                            approved_only=approved_only)
    return next(e.translation for e in translate(recipe, translator) if isinstance(e, TranslationFinished))


def boil_results(translation):
    return [r for step in translation.steps for r in step.actions if r.reduction.action.verb == "boil"]


@pytest.mark.parametrize("validator", [None, PassingKitchen()], ids=["no kitchen check", "kitchen check"])
def test_no_plan_is_cached_once_and_the_model_is_not_asked_again(library, validator):
    first_model = ScriptedModel(dict(NOTHING_ADMISSIBLE))
    first = translated(first_model, library, validator)
    # boil egg went to the model; boil potato found the no-plan entry it left; mash went to the model.
    assert [p.splitlines()[-1].split("(")[0] for p in first_model.prompts] == ["def boil", "def mash"]
    assert (first.stats.llm_calls, first.stats.library_hits, first.stats.no_plan_hits) == (2, 1, 1)
    [entry] = [e for e in library.entries() if e.verb == "boil"]
    assert (entry.body, entry.status, entry.validation, entry.problems) == ("", Status.PENDING, "failed",
                                                                           (NO_PLAN_PROBLEM,))
    assert entry.example == (("$what", "egg"),)
    if validator is not None:
        assert "boil" not in validator.checked  # nothing to run in the kitchen

    again = ScriptedModel(dict(NOTHING_ADMISSIBLE))
    second = translated(again, library, validator)
    assert again.calls == 0 and second.stats.llm_calls == 0
    assert (second.stats.library_hits, second.stats.no_plan_hits) == (3, 2)
    for result in boil_results(second):
        assert result.plan == () and result.reduction.source == Source.LIBRARY
        assert result.reduction.entry_id == entry.id and result.entry_problems == (NO_PLAN_PROBLEM,)
    assert second.steps[0].problems == first.steps[0].problems == ("no admissible plan for boil(egg)",)
    assert len(library.entries()) == 2  # nothing added the second time


def test_an_entry_without_a_plan_is_no_verb_of_later_prompts(library):
    model = ScriptedModel(dict(NOTHING_ADMISSIBLE))
    translation = translated(model, library)
    mash_prompt, mash_grammar = model.prompts[-1], model.grammars[-1]
    assert "def mash(" in mash_prompt
    assert "import boil" not in mash_prompt and '"boil("' not in mash_grammar
    [mash] = [r for step in translation.steps for r in step.actions if r.reduction.action.verb == "mash"]
    assert "boil(potato)" in mash.reduction.dropped  # not a verb it may call
    assert [e.verb for e in library.live("recipe")] == ["mash"]


def test_rejecting_it_makes_the_model_try_again(library):
    translated(ScriptedModel(dict(NOTHING_ADMISSIBLE)), library)
    entry = library.lookup("recipe", "boil", ("what",))
    library.set_status(entry.id, Status.REJECTED, by="ann")
    better = ScriptedModel({"boil": BOIL.replace("$what", "egg")})
    translation = translated(better, library)
    assert [p.splitlines()[-1].split("(")[0] for p in better.prompts] == ["def boil"]  # mash is cached
    assert [r.reduction.source for r in boil_results(translation)] == [Source.LLM, Source.LIBRARY]
    assert library.lookup("recipe", "boil", ("what",)).body == BOIL


def test_approving_it_is_refused_even_with_force(library):
    translated(ScriptedModel(dict(NOTHING_ADMISSIBLE)), library)
    entry = library.lookup("recipe", "boil", ("what",))
    for force in (False, True):
        with pytest.raises(UserError, match="has no plan: there is nothing to approve") as refused:
            library.set_status(entry.id, Status.APPROVED, by="ann", force=force)
        assert "cook2ltl library edit" in refused.value.hint
    assert library.get(entry.id).status == Status.PENDING and library.reviews(entry.id) == ()
    env = {**os.environ, "COOK2LTL_USER": "ann", "HF_HUB_OFFLINE": "1"}
    command = subprocess.run([sys.executable, "-m", "cook2ltl", "library", "approve", str(entry.id), "--force",
                              "--library", str(library.path)], capture_output=True, text=True, timeout=120, env=env)
    assert command.returncode == 2 and "nothing to approve" in command.stderr


def test_approved_only_mode_skips_it_as_pending(library):
    translated(ScriptedModel(dict(NOTHING_ADMISSIBLE)), library)
    lab = ScriptedModel(dict(NOTHING_ADMISSIBLE))
    translation = translated(lab, library, approved_only=True)
    assert lab.calls == 3 and translation.stats.no_plan_hits == 0
    assert len(library.entries()) == 2  # the pending entries are not cached over


def test_an_edit_gives_it_a_body_that_is_then_reused(library, tmp_path):
    from cook2ltl.cli import app

    translated(ScriptedModel(dict(NOTHING_ADMISSIBLE)), library)
    entry = library.lookup("recipe", "boil", ("what",))
    runner = CliRunner()
    listed = runner.invoke(app, ["library", "list", "--library", str(library.path)], env={"COLUMNS": "200"})
    assert "boil(what) (no plan)" in listed.output and "mash(what) (no plan)" not in listed.output
    shown = runner.invoke(app, ["library", "show", str(entry.id), "--library", str(library.path)])
    assert "(no plan)" in shown.output and NO_PLAN_PROBLEM.split(";")[0] in shown.output

    body = tmp_path / "boil.txt"
    body.write_text(BOIL, encoding="utf-8")
    edited = runner.invoke(app, ["library", "edit", str(entry.id), "--body-file", str(body), "--no-validate",
                                 "--library", str(library.path), "--by", "ann"])
    assert edited.exit_code == 0, edited.output
    now = library.get(entry.id)
    assert (now.body, now.version, now.validation, now.problems) == (BOIL, 2, "unchecked", ())
    assert [v.body for v in library.history(entry.id)] == ["", BOIL]
    history = runner.invoke(app, ["library", "history", str(entry.id), "--library", str(library.path)],
                            env={"COLUMNS": "200"})
    assert "(no plan)" in history.output

    model = ScriptedModel(dict(NOTHING_ADMISSIBLE))
    translation = translated(model, library)
    assert model.calls == 0 and translation.stats.no_plan_hits == 0
    assert [[c.text() for c in r.plan][:2] for r in boil_results(translation)] == [
        ["pick_up(egg)", "put(egg, pot)"], ["pick_up(potato)", "put(potato, pot)"]]
    assert library.set_status(entry.id, Status.APPROVED, by="ann").status == Status.APPROVED


def test_export_and_import_keep_it_as_an_entry_without_a_plan(library, tmp_path):
    translated(ScriptedModel(dict(NOTHING_ADMISSIBLE)), library)
    exported = tmp_path / "lab.json"
    export_library(library, exported)
    other = Library(tmp_path / "other.sqlite")
    try:
        report = import_library(other, exported, "bob")
        assert sorted(report.added) == ["recipe boil(what)", "recipe mash(what)"]
        imported = other.lookup("recipe", "boil", ("what",))
        assert (imported.body, imported.validation, imported.problems) == ("", "failed", (NO_PLAN_PROBLEM,))
        assert [e.verb for e in other.live("recipe")] == ["mash"]
        assert import_library(other, exported, "bob").unchanged  # the same file again: nothing changes
    finally:
        other.close()

    lab = Library(tmp_path / "lab.sqlite")  # a lab with a body for boil: no plan never replaces it
    try:
        given = lab.add("recipe", "boil", ("what",), BOIL, "lab", "x")
        kept = import_library(lab, exported, "bob", replace_pending=True)
        assert kept.conflicts == (f"recipe boil(what): the file has no plan for it; entry {given.id} keeps its body",)
        assert (lab.get(given.id).body, lab.get(given.id).version) == (BOIL, 1)
    finally:
        lab.close()

    data = json.loads(exported.read_text(encoding="utf-8"))
    data["entries"][0]["status"] = "approved"
    exported.write_text(json.dumps(data), encoding="utf-8")
    third = Library(tmp_path / "third.sqlite")
    with pytest.raises(UserError, match=r"entry 1: an entry with no plan \(an empty \"body\"\) cannot be approved"):
        import_library(third, exported, "bob")
    assert third.entries() == ()
    third.close()
