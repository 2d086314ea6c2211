"""Completions decoded together in one llama.cpp batch, with the tiny test model: each thread gets a plan its
grammar admits, lanes are given back, and a lane waits for a free one when all are taken."""

import threading

import pytest

from cook2ltl.domain.actions import Action
from cook2ltl.reduce.action import parameter
from cook2ltl.reduce.batched import BatchedLlamaModel
from cook2ltl.reduce.grammar import admits, vocabulary
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.reduction import ReductionSettings, reduce_action
from tests.reduce.test_llama_backend import TINY, tiny_path  # noqa: F401 (a fixture)

PRIMITIVES = load_primitives("recipe")
ACTIONS = [Action(verb, (parameter("what", what),)) for verb, what in
           (("boil", "the egg"), ("chill", "the milk"), ("melt", "the butter"), ("wash", "the apple"))]


@pytest.mark.parametrize("lanes", [2, 4])
def test_threads_sharing_the_model_each_get_an_admissible_plan(tiny_path, lanes):  # noqa: F811
    model = BatchedLlamaModel(TINY, tiny_path, lanes)
    plans, failures = {}, []

    def reduce(task):
        try:
            plans[task.verb] = reduce_action(task, PRIMITIVES, [], model, ReductionSettings(max_lines=3))
        except Exception as error:  # a thread's failure is the test's
            failures.append(error)

    threads = [threading.Thread(target=reduce, args=(task,)) for task in ACTIONS]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(timeout=120)
    assert not failures and sorted(plans) == sorted(a.verb for a in ACTIONS)
    for task in ACTIONS:
        reduction = plans[task.verb]
        assert 1 <= len(reduction.body) <= 3 and reduction.dropped == ()
        assert all(admits(vocabulary(PRIMITIVES, [], task), call) for call in reduction.body)
    assert sorted(model._steps.idle) == list(range(1, lanes + 1)) and model._steps.open_lanes == 0
    again = reduce_action(ACTIONS[0], PRIMITIVES, [], model, ReductionSettings(max_lines=3))
    assert again.body == plans["boil"].body  # alone in the batch, greedy decoding gives it again
    model.close()
