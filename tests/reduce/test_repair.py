"""The repair loop: a scripted model, the real kitchen check, a real SQLite library."""

import pytest

from cook2ltl.domain.actions import Source
from cook2ltl.errors import UserError
from cook2ltl.library import Library
from cook2ltl.library.store import Status
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline.rates import rates
from cook2ltl.pipeline.records import TranslationFinished
from cook2ltl.pipeline.translator import Translator, translate
from cook2ltl.reduce.primitives import load_primitives
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel
from tests.reduce.gbnf import accepts
from tests.reduce.kitchen_validators import validators  # noqa: F401  (a fixture)

TEXT = "Microwave the potato."
SPANS = {TEXT: [("VERB", "Microwave"), ("WHAT", "the potato")]}
BAD = "open(microwave)\nput(potato, microwave)\nclose(microwave)\nturn_on(microwave)"
GOOD = "open(microwave)\npick_up(potato)\nput(potato, microwave)\nclose(microwave)\nturn_on(microwave)"


@pytest.fixture
def library(tmp_path):
    opened = Library(tmp_path / "library.sqlite")
    yield opened
    opened.close()


def translated(translator, text=TEXT, spans=SPANS):
    recipe = parse_recipe(text, ScriptedSpans(spans), ScriptedDependencies())
    return next(e for e in translate(recipe, translator) if isinstance(e, TranslationFinished)).translation


def test_a_failing_plan_is_repaired_with_the_failure_in_the_prompt(validators, library):
    model = ScriptedModel({"microwave": [BAD, GOOD]})
    translator = Translator(load_primitives("ai2thor"), model, library, validator=validators("ai2thor"))
    translation = translated(translator)
    result = translation.steps[0].actions[0]
    assert result.validation.passed and [c.text() for c in result.attempts[0].body] == BAD.splitlines()
    stats = translation.stats
    assert (stats.llm_calls, stats.repair_calls, stats.checked, stats.validated, stats.repaired) == (1, 1, 1, 1, 1)
    assert model.calls == 2 and stats.prompt_tokens == sum(len(p.split()) for p in model.prompts)
    assert stats.kitchen_seconds > result.validation.seconds > 0  # the failed run in the kitchen counts too
    # The problem under the header, then the lines before the failing one, kept; the static prefix unchanged.
    assert model.prompts[1].endswith(
        "def microwave(potato: what):\n    # this plan failed: line 2 put(potato, microwave): the agent holds nothing; "
        "the plan must pick up potato first\n    # this plan failed: microwave(potato): goal state not reached: potato "
        "is not hot at the end\n    open(microwave)\n")
    # The grammar keeps the model from writing a put again right there.
    assert accepts(model.grammars[1], "    pick_up(potato)\n    put(potato, microwave)\n\n")
    assert not accepts(model.grammars[1], "    put(potato, fridge)\n\n")
    assert accepts(model.grammars[0], "    put(potato, microwave)\n\n")
    assert model.statics[0] == model.statics[1] and "pick_up(" in model.grammars[1]
    entry = library.entries()[0]
    assert entry.body.splitlines()[1] == "pick_up($what)" and entry.validation == "passed"
    assert entry.status == Status.PENDING and entry.problems == () and dict(entry.example) == {"$what": "potato"}
    assert rates(translation).validated_rate == 1.0 and rates(translation).executability == 1.0


def test_a_plan_that_keeps_failing_is_cached_pending_and_failed(validators, library):
    model = ScriptedModel({"microwave": BAD})
    translator = Translator(load_primitives("ai2thor"), model, library, validator=validators("ai2thor"), repairs=2)
    translation = translated(translator)
    assert model.calls == 3 and translation.stats.repair_calls == 2 and translation.stats.validated == 0
    entry = library.entries()[0]
    assert entry.status == Status.PENDING and entry.validation == "failed"
    assert entry.problems == ("line 2 put(potato, microwave): the agent holds nothing; "
                              "the plan must pick up potato first",
                              "microwave(potato): goal state not reached: potato is not hot at the end")
    assert rates(translation).validated_rate == 0.0
    # Never approved by itself, and a reviewer must insist to approve it.
    with pytest.raises(UserError, match="(?i)fail"):
        library.set_status(entry.id, Status.APPROVED, by="tester")
    assert library.get(entry.id).status == Status.PENDING


def test_no_repairs_asked(validators, library):
    model = ScriptedModel({"microwave": [BAD, GOOD]})
    translation = translated(Translator(load_primitives("ai2thor"), model, library,
                                        validator=validators("ai2thor"), repairs=0))
    assert model.calls == 1 and translation.stats.checked == 1 and translation.stats.validated == 0


def test_an_unchecked_plan_is_not_repaired(validators, library):
    text = "Blend the ice."
    model = ScriptedModel({"blend": "put(ice, blender)\nturn_on(blender)"})
    translation = translated(Translator(load_primitives("recipe"), model, library, validator=validators("recipe")),
                             text, {text: [("VERB", "Blend"), ("WHAT", "the ice")]})
    assert model.calls == 1 and translation.stats.checked == 0
    assert library.entries()[0].validation == "unchecked"
    assert rates(translation).validated_rate == 0.0


def test_a_library_hit_is_not_validated_again(validators, library):
    translator = Translator(load_primitives("ai2thor"), ScriptedModel({"microwave": GOOD}), library,
                            validator=validators("ai2thor"))
    translated(translator)
    again = translated(translator, "Microwave the apple.", {"Microwave the apple.": [("VERB", "Microwave"),
                                                                                     ("WHAT", "the apple")]})
    hit = again.steps[0].actions[0]
    assert hit.reduction.source == Source.LIBRARY and hit.validation is None and again.stats.checked == 0
    assert rates(again).new_reductions == 0 and rates(again).validated_rate is None


def test_reuse_respects_review_status(library):
    primitives = load_primitives("ai2thor")
    model = ScriptedModel({"microwave": [GOOD, BAD, GOOD]})
    translated(Translator(primitives, model, library))
    first = library.entries()[0]
    # Lab mode: the pending entry is not used; the model is asked, and its plan is not cached over the pending one.
    lab = translated(Translator(primitives, model, library, approved_only=True))
    assert lab.steps[0].actions[0].reduction.source == Source.LLM and model.calls == 2
    assert [e.id for e in library.entries()] == [first.id]
    library.set_status(first.id, Status.APPROVED, by="tester")
    approved = translated(Translator(primitives, model, library, approved_only=True))
    assert approved.steps[0].actions[0].reduction.entry_id == first.id and model.calls == 2
    # A rejected entry is never reused: the action is reduced again and cached anew.
    library.set_status(first.id, Status.REJECTED, by="tester")
    rejected = translated(Translator(primitives, model, library))
    assert rejected.steps[0].actions[0].reduction.source == Source.LLM and model.calls == 3
    assert rejected.steps[0].actions[0].reduction.entry_id != first.id


def test_a_failed_entry_reused_says_so(validators, library):
    translator = Translator(load_primitives("ai2thor"), ScriptedModel({"microwave": BAD}), library,
                            validator=validators("ai2thor"), repairs=0)
    translated(translator)
    hit = translated(translator).steps[0].actions[0]
    assert hit.reduction.source == Source.LIBRARY and hit.entry_validation == "failed"
    assert hit.entry_problems[0].startswith("line 2 put(potato, microwave)")


def test_a_goal_not_reached_at_the_end_keeps_the_plan_to_add_to_it(validators, library):
    text = "Chill the apple until cold."
    spans = {text: [("VERB", "Chill"), ("WHAT", "the apple"), ("TIME", "until cold")]}
    model = ScriptedModel({"chill": ["pick_up(apple)\nput(apple, countertop)",
                                     "pick_up(apple)\nput(apple, countertop)\nopen(fridge)\npick_up(apple)\n"
                                     "put(apple, fridge)"]})
    translation = translated(Translator(load_primitives("ai2thor"), model, library, validator=validators("ai2thor")),
                             text, spans)
    assert model.prompts[1].endswith("    pick_up(apple)\n    put(apple, countertop)\n")
    assert "goal state not reached: apple is not cold at the end" in model.prompts[1]
    assert translation.stats.repaired == 1 and len(translation.steps[0].actions[0].reduction.body) == 5


def test_repairs_at_the_same_place_avoid_every_name_that_failed_there(validators, library):
    model = ScriptedModel({"microwave": ["open(microwave)\nturn_on(potato)", "open(microwave)\nclose(potato)",
                                         GOOD]})
    translation = translated(Translator(load_primitives("ai2thor"), model, library, validator=validators("ai2thor")))
    assert translation.stats.repaired == 1 and model.calls == 3
    assert not accepts(model.grammars[1], "    turn_on(microwave)\n\n")
    assert accepts(model.grammars[1], "    close(microwave)\n\n")
    assert not accepts(model.grammars[2], "    turn_on(microwave)\n\n")
    assert not accepts(model.grammars[2], "    close(microwave)\n\n")
    assert accepts(model.grammars[2], "    pick_up(potato)\n    turn_on(microwave)\n\n")
