"""One action through Algorithm 1 with the real default model under the real grammar (llama.cpp)."""

import pytest

from cook2ltl.assembly.backends import DEFAULT_MODEL, load_model
from cook2ltl.assembly.manifest import ModelState, load_manifest, state_of
from cook2ltl.domain.actions import Source
from cook2ltl.library import Library
from cook2ltl.ltl import to_spot
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline.records import TranslationFinished
from cook2ltl.pipeline.translator import Translator, translate
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.reduction import ReductionSettings
from tests.fakes import ScriptedDependencies, ScriptedSpans


def test_refrigerate_the_apple_with_the_default_model(tmp_path):
    if state_of(load_manifest()[DEFAULT_MODEL], verify_hash=False) != ModelState.READY:
        pytest.fail(f"model not provisioned: {DEFAULT_MODEL}; run `make models`")
    text = "Refrigerate the apple."
    parsed = parse_recipe(text, ScriptedSpans({text: [("VERB", "Refrigerate"), ("WHAT", "the apple")]}),
                          ScriptedDependencies())
    library = Library(tmp_path / "library.sqlite")
    translator = Translator(load_primitives("ai2thor"), load_model(), library, settings=ReductionSettings(max_lines=6))
    translation = [e for e in translate(parsed, translator) if isinstance(e, TranslationFinished)][0].translation
    library.close()
    step = translation.steps[0]
    reduction = step.actions[0].reduction
    assert reduction.source == Source.LLM and reduction.dropped == () and step.problems == ()
    assert "put(apple, fridge)" in [call.text() for call in step.actions[0].plan]
    assert translation.stats.llm_calls == 1 and translation.stats.completion_tokens > 0
    assert '"put(apple, fridge)"' in to_spot(step.formula)
