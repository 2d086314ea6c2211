"""Property tests: any text through the recipe parser, the LTL parser and the pipeline (with fakes) gives a
result or a UserError / LTLSyntaxError, never another exception."""

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cook2ltl.domain.settings import Limits
from cook2ltl.errors import UserError
from cook2ltl.ltl.ast import Formula
from cook2ltl.ltl.parser import LTLSyntaxError, parse
from cook2ltl.ltl.printer import to_spot, to_unicode
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline.records import TranslationFinished
from cook2ltl.pipeline.translator import Translator, translate
from cook2ltl.reduce.primitives import load_primitives
from tests.fakes import ScriptedDependencies
from tests.reduce.fake_model import ScriptedModel
from tests.reliability.hostile import HAND_MADE, TRIED, WordSpans, hostile_text

PROPERTY = settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
LTL_PIECES = ["F", "G", "X", "X[!]", "U", "R", "W", "M", "!", "&", "|", "->", "<->", "(", ")", "a", "b",
              "pick_up(knife)", '"slice(tomato, knife)"', "true", "false", "◇", "□", "○", "𝒰", "∧", "∨", "¬",
              "→", ",", '"', "[]", "<>", " ", "\n", "é", "\u200b"]
ltl_text = st.one_of(st.text(max_size=80), st.lists(st.sampled_from(LTL_PIECES), max_size=40).map(" ".join),
                     st.lists(st.sampled_from(LTL_PIECES), max_size=40).map("".join))


@PROPERTY
@given(hostile_text)
def test_any_recipe_text_parses_or_is_a_user_error(text):
    TRIED["recipe parser"] += 1
    try:
        recipe = parse_recipe(text, WordSpans(), ScriptedDependencies(), Limits())
    except UserError as error:
        assert error.message and "\n" not in error.message
        return
    assert recipe.steps
    for step in recipe.steps:
        assert recipe.text[step.sentence.start:step.sentence.end] == step.sentence.text
        assert len(recipe.text) == len(text)  # hidden characters became spaces, one for one
        for span in step.spans:
            assert step.sentence.start <= span.start < span.end <= step.sentence.end
            assert recipe.text[span.start:span.end] == span.text


@PROPERTY
@given(ltl_text)
def test_any_text_is_a_formula_or_a_clean_ltl_syntax_error(text):
    TRIED["LTL parser"] += 1
    try:
        formula = parse(text)
    except LTLSyntaxError as error:
        assert error.line >= 1 and error.column >= 1 and "^" in error.pointer()
        return
    assert isinstance(formula, Formula)
    assert parse(to_spot(formula)) == formula  # what we print, we read back
    assert parse(to_unicode(formula)) == formula


@pytest.fixture(scope="module")
def recipe_primitives():
    return load_primitives("recipe")


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(hostile_text)
def test_any_recipe_translates_with_a_scripted_model_or_is_a_user_error(recipe_primitives, text):
    TRIED["pipeline (fakes)"] += 1
    model = ScriptedModel({})  # writes nothing: every non-primitive action has no plan, reported as a problem
    try:
        parsed = parse_recipe(text, WordSpans(), ScriptedDependencies(), Limits())
    except UserError:
        return
    events = list(translate(parsed, Translator(recipe_primitives, model, None, variant="AR")))
    assert isinstance(events[-1], TranslationFinished)
    translation = events[-1].translation
    assert len(translation.steps) == len(parsed.steps)
    for step in translation.steps:
        for result in step.actions:
            assert all(call.name.isidentifier() for call in result.plan)


def test_the_hand_made_cases_are_all_handled():
    for text in HAND_MADE:
        TRIED["hand-made recipe"] += 1
        try:
            recipe = parse_recipe(text, WordSpans(), ScriptedDependencies(), Limits())
        except UserError as error:
            assert "empty" in error.message or "limit" in error.message
        else:
            assert recipe.steps
