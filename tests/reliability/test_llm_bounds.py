"""A reduction by the real (tiny) model is bounded in time and can be cancelled; neither leaves half a plan."""

import threading
import time

import pytest

from cook2ltl.assembly.manifest import ModelState, load_manifest, model_path, state_of
from cook2ltl.domain.actions import Action
from cook2ltl.reduce.action import parameter
from cook2ltl.reduce.llm import GenerationCancelled, GenerationStopped, LlamaModel
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.reduction import ReductionSettings, reduce_action

TINY = "smollm2-135m"
# Comments make the tiny model write long plans, so there is generation to interrupt.
LONG = ReductionSettings(max_lines=12, comments=True)


@pytest.fixture(scope="module")
def tiny():
    entry = load_manifest()[TINY]
    if state_of(entry, verify_hash=False) != ModelState.READY:
        pytest.fail(f"model not provisioned: {TINY}; run `make models`")
    model = LlamaModel(TINY, model_path(entry), threads=2)
    simmer = Action("simmer", (parameter("what", "the sauce"),))
    # Load, and evaluate the static prompt now: the bounds are checked between prompt batches of 512 tokens
    # (seconds each on a busy machine) and between generated tokens; these tests time the latter.
    reduce_action(simmer, load_primitives("recipe"), [], model, ReductionSettings(1, comments=True))
    return model


def boil():
    return Action("boil", (parameter("what", "the eggs"), parameter("where", "in a pot")))


def test_a_reduction_past_its_time_limit_stops_with_a_clear_error(tiny):
    tiny.time_limit = 0.05
    try:
        started = time.perf_counter()
        with pytest.raises(GenerationStopped, match="took more than 0.05 s") as raised:
            reduce_action(boil(), load_primitives("recipe"), [], tiny, LONG)
        assert time.perf_counter() - started < 10
        assert "llm_seconds" in raised.value.hint
    finally:
        tiny.time_limit = 120.0


def test_cancelling_stops_generation_at_once(tiny):
    """Cancel lands between two generated tokens (or two batches of a cold prompt, not timed here)."""
    tiny.cancel = threading.Event()
    timer = threading.Timer(0.3, tiny.cancel.set)
    timer.start()
    started = time.perf_counter()
    try:
        with pytest.raises(GenerationCancelled):
            reduce_action(boil(), load_primitives("recipe"), [], tiny, LONG)
    finally:
        timer.cancel()
        tiny.cancel = threading.Event()
    assert time.perf_counter() - started < 5


def test_within_the_limits_a_reduction_still_completes(tiny):
    reduction = reduce_action(boil(), load_primitives("recipe"), [], tiny, ReductionSettings(3))
    assert reduction.body and reduction.usage.completion_tokens <= 3 * 40


def test_the_time_limit_comes_from_the_settings(tmp_path, monkeypatch):
    from cook2ltl.assembly.backends import load_model
    from cook2ltl.reduce.llm import DEFAULT_TIME_LIMIT

    monkeypatch.setenv("COOK2LTL_CONFIG", str(tmp_path / "config.toml"))
    assert load_model(TINY).time_limit == DEFAULT_TIME_LIMIT
    (tmp_path / "config.toml").write_text("[limits]\nllm_seconds = 7.5\n")
    assert load_model(TINY).time_limit == 7.5
