"""Effects of verbs the verb-effect table lacks: written by the model under a grammar of observable states,
kept with the library entry, and reused from it."""

import pytest

from cook2ltl.library.store import Library
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline.records import Variant
from cook2ltl.pipeline.translator import Translator, translate
from cook2ltl.reduce.effect_writer import effect_prompt, write_effect
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.world.effects import verb_table
from cook2ltl.world.kitchens import grounding
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel
from tests.world.test_recipe_world import act

PRIMITIVES = load_primitives("recipe")


@pytest.fixture(scope="module")
def kitchen():
    return grounding(PRIMITIVES)


def test_the_prompt_shows_the_tables_own_entries():
    prompt = effect_prompt(verb_table())
    assert "def boil(food: what):\n    boiled(food)\n" in prompt
    assert "def freeze(food: what):\n    frozen(food)\n    in(food, freezer)\n" in prompt  # whole entries
    assert "done(" not in prompt and "ready(" not in prompt


def test_the_model_writes_only_observable_atoms_over_the_actions_objects(kitchen):
    state = kitchen.start(["salad", "dressing"]).state
    model = ScriptedModel({"zhuzh": "ready(salad)\ncombined(salad)\nin(dressing, salad)\npick_up(salad)"})
    templates, _ = write_effect(act("zhuzh", what="salad", how="dressing"), model, kitchen.world, state, verb_table())
    assert templates == (("combined", ("what",)),)  # one atom: the model's best guess
    offered = set(model.grammars[0].splitlines())
    assert "combined(salad)" in offered and "hot(dressing)" in offered and "in(dressing, salad)" in offered
    assert "in(salad, fridge)" in offered  # no place named: the table's kitchen places
    assert not any(line.startswith(("ready(", "done(", "pick_up(")) for line in offered)
    assert not any("egg" in line for line in offered)  # only the action's objects and the table's places


RECIPE = "Zhuzh the salad."
SPANS = {RECIPE: [("VERB", "Zhuzh"), ("WHAT", "the salad")]}


def test_a_written_effect_is_kept_with_the_entry_and_reused_without_asking_again(kitchen, tmp_path):
    library = Library(tmp_path / "library.sqlite")
    model = ScriptedModel({"zhuzh": "combined(salad)\npick_up(salad)"})
    translator = Translator(PRIMITIVES, model, library, Variant.AR_LIBRARY, grounding=kitchen)

    stats = []

    def run():
        parsed = parse_recipe(RECIPE, ScriptedSpans(SPANS), ScriptedDependencies())
        translation = list(translate(parsed, translator))[-1].translation
        stats.append(translation.stats)
        return translation.steps[0].actions[0]

    first = run()
    assert stats[-1].effect_calls == 1
    assert first.check.effect == (("combined", "salad"),) and first.check.effect_reached
    (entry,) = library.entries()
    assert entry.effect == ("combined(what)",)
    asked = model.calls
    again = run()
    assert model.calls == asked and stats[-1].effect_calls == 0  # neither the plan nor the effect is asked again
    assert again.check.effect == (("combined", "salad"),) and again.check.effect_reached
