"""The llama.cpp backend with the tiny test model: grammar honoured, results independent of the cache."""

import pytest

from cook2ltl.assembly.manifest import ModelState, load_manifest, model_path, state_of
from cook2ltl.domain.actions import Action
from cook2ltl.reduce.action import parameter
from cook2ltl.reduce.grammar import admits, vocabulary
from cook2ltl.reduce.llm import LlamaModel
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.reduction import ReductionSettings, reduce_action

TINY = "smollm2-135m"
SETTINGS = ReductionSettings(max_lines=2)


@pytest.fixture(scope="module")
def tiny_path():
    entry = load_manifest()[TINY]
    if state_of(entry, verify_hash=False) != ModelState.READY:
        pytest.fail(f"model not provisioned: {TINY}; run `make models`")
    return model_path(entry)


def action(verb, *params):
    return Action(verb, tuple(parameter(category, text) for category, text in params))


def test_every_line_is_admissible(tiny_path):
    primitives = load_primitives("recipe")
    task = action("simmer", ("what", "the sauce"), ("time", "for 20 minutes"))
    reduction = reduce_action(task, primitives, [], LlamaModel(TINY, tiny_path), ReductionSettings(3, comments=True))
    assert 1 <= len(reduction.body) <= 3 and reduction.dropped == ()
    assert all(admits(vocabulary(primitives, [], task), call) for call in reduction.body)
    assert reduction.usage.completion_tokens > 0 and reduction.usage.prompt_tokens > 300


def test_results_do_not_depend_on_the_cache(tiny_path, tmp_path):
    thor = load_primitives("ai2thor")
    potato, bread = action("microwave", ("what", "the potato")), action("cut", ("what", "the bread"))
    first = LlamaModel(TINY, tiny_path, state_dir=tmp_path)
    in_order = [reduce_action(a, thor, [], first, SETTINGS).body for a in (potato, bread)]
    assert len(list(tmp_path.glob("*.state"))) == 1  # the evaluated static prefix, saved once
    second = LlamaModel(TINY, tiny_path, state_dir=tmp_path)
    reversed_order = [reduce_action(a, thor, [], second, SETTINGS).body for a in (bread, potato)]
    assert second.restored is False  # the second action reused the prefix from memory
    assert reversed_order[::-1] == in_order
    third = LlamaModel(TINY, tiny_path, state_dir=tmp_path)
    assert reduce_action(potato, thor, [], third, SETTINGS).body == in_order[0] and third.restored


@pytest.mark.parametrize("shortlist", [64, 1])  # 1: the best token is often refused, so the full check runs
def test_shortlist_decoding_gives_what_the_full_grammar_sampler_gives(tiny_path, monkeypatch, shortlist):
    from llama_cpp import LlamaGrammar, StoppingCriteriaList

    from cook2ltl.reduce import decoding
    from cook2ltl.reduce.body import loops, read_body
    from cook2ltl.reduce.grammar import to_gbnf
    from cook2ltl.reduce.prompt import build_prompt

    monkeypatch.setattr(decoding, "SHORTLIST", shortlist)
    primitives, model = load_primitives("ai2thor"), LlamaModel(TINY, tiny_path)
    cut_by_loops = 0
    # The tiny model goes round in circles on these: `loops` ends the completion mid-plan.
    for task in (action("chop", ("what", "the tomato")), action("cut", ("what", "the bread"))):
        prompt = build_prompt(primitives, [], task, False, None)
        grammar = to_gbnf(vocabulary(primitives, [], task), 12, comments=False)
        ours = model.complete(prompt.static, prompt.dynamic, grammar, 120, loops)
        llama = model._llama
        prefix = llama.tokenize(prompt.static.encode())
        tokens = prefix + llama.tokenize(prompt.dynamic.encode(), add_bos=False)
        model._keep_only(llama, prefix, prompt.static, deadline=float("inf"))  # the prefix evaluated as ours
        completed = lambda ids, _: loops(llama.detokenize(ids[len(tokens):].tolist()).decode(errors="ignore"))  # noqa: E731
        full = llama.create_completion(tokens, max_tokens=120, temperature=0.0, repeat_penalty=1.0,
                                       grammar=LlamaGrammar.from_string(grammar, verbose=False),
                                       stopping_criteria=StoppingCriteriaList([completed]))
        assert ours.text == full["choices"][0]["text"] and ours.text.strip()
        assert ours.usage.completion_tokens == full["usage"]["completion_tokens"]
        assert read_body(ours.text)[1] == ()  # no unfinished line
        cut_by_loops += loops(ours.text)
    assert cut_by_loops  # the case where the token that ends the completion matters
