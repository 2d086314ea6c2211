"""Recipes translated side by side, each translator with its own library connection: every recipe once, and a
key two of them need at the same time asked of the model once."""

import threading
import time

import pytest

from cook2ltl.library import Library
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline.side_by_side import translate_side_by_side
from cook2ltl.pipeline.translator import Translator
from cook2ltl.reduce.primitives import load_primitives
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel

PRIMITIVES = load_primitives("recipe")
SPANS = {"Boil the egg.": [("VERB", "Boil"), ("WHAT", "the egg")],
         "Chill the milk.": [("VERB", "Chill"), ("WHAT", "the milk")],
         "Add the egg.": [("VERB", "Add"), ("WHAT", "the egg")],
         "Add in the egg.": [("VERB", "Add in"), ("WHAT", "the egg")]}


class SlowModel(ScriptedModel):
    """Takes a while to answer, so that two translations ask at the same time; counts overlapping calls."""

    def __init__(self, answers):
        super().__init__(answers)
        self.inside, self.most_inside, self.lock = 0, 0, threading.Lock()

    def complete(self, *args, **kwargs):
        with self.lock:
            self.inside += 1
            self.most_inside = max(self.most_inside, self.inside)
        time.sleep(0.2)
        try:
            return super().complete(*args, **kwargs)
        finally:
            with self.lock:
                self.inside -= 1


@pytest.fixture
def libraries(tmp_path):
    opened = [Library(tmp_path / "library.sqlite") for _ in range(3)]
    yield opened
    for library in opened:
        library.close()


def recipes(*texts):
    return [parse_recipe(text, ScriptedSpans(SPANS), ScriptedDependencies()) for text in texts]


def test_every_recipe_once_and_a_shared_key_asked_once(libraries):
    model = SlowModel({"boil": "pick_up(egg)\nput(egg, pot)", "chill": "open(fridge)"})
    translators = [Translator(PRIMITIVES, model, library) for library in libraries]
    texts = ["Boil the egg.", "Chill the milk.", "Boil the egg.", "Boil the egg.", "Chill the milk.", "Boil the egg."]
    done = dict(translate_side_by_side(recipes(*texts), translators))
    assert sorted(done) == list(range(len(texts)))
    assert model.calls == 2  # boil and chill, once each: the other recipes waited and found the entry
    assert model.most_inside == 2  # boil and chill were asked side by side
    plans = [[c.text() for r in done[i].steps[0].actions for c in r.plan] for i in (0, 2, 3, 5)]
    assert plans == [["pick_up(egg)", "put(egg, pot)"]] * 4
    assert sum(t.stats.llm_calls for t in done.values()) == 2 and len(libraries[0].entries()) == 2


def test_an_action_another_verb_of_its_table_row_may_serve_waits_for_it(libraries):
    model = SlowModel({"add": "pick_up(egg)\nput(egg, bowl)", "add_in": "pick_up(egg)\nput(egg, pot)"})
    translators = [Translator(PRIMITIVES, model, library) for library in libraries[:2]]
    done = dict(translate_side_by_side(recipes("Add the egg.", "Add in the egg."), translators))
    assert model.calls == 1  # one waited for the other (the table reads add_in as add) and reused its entry
    assert sorted(done[i].steps[0].actions[0].reuse is None for i in (0, 1)) == [False, True]


def test_a_failure_is_raised_and_stops_the_rest(libraries):
    class Broken(ScriptedModel):
        def complete(self, *args, **kwargs):
            raise RuntimeError("the model broke")

    translators = [Translator(PRIMITIVES, Broken({}), library) for library in libraries[:2]]
    with pytest.raises(RuntimeError, match="the model broke"):
        list(translate_side_by_side(recipes("Boil the egg.", "Chill the milk.", "Boil the egg."), translators))
