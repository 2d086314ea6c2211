"""Greedy decoding under a GBNF grammar that asks the grammar about the model's best few tokens only.

llama.cpp's grammar sampler tries every token of the vocabulary at every step (152,000 for Qwen), which here
cost almost half the time of a reduction. At temperature 0 the next token is the highest-scoring one the
grammar admits, so the SHORTLIST best tokens are tried first and the whole vocabulary only when the grammar
refuses them all: the same tokens come out, several times cheaper.

llama_cpp is imported by the caller before any of this runs.
"""

from __future__ import annotations

import ctypes
from collections.abc import Callable, Iterator
from typing import Protocol

import numpy as np

SHORTLIST = 64
# llama_token_data, laid out as the C struct: token id, logit, probability.
_TOKEN_DATA = np.dtype([("id", np.int32), ("logit", np.float32), ("p", np.float32)], align=True)


class GrammarRejected(ValueError):
    """llama.cpp could not parse the grammar."""


class Lane(Protocol):
    """One sequence of evaluated tokens: a llama.cpp context of its own (`SoloLane`), or one of several sequences
    decoded together in one batch (`cook2ltl.reduce.batched`)."""

    n_tokens: int  # how many tokens are evaluated; lowering it makes the next `evaluate` go on from there

    def evaluate(self, tokens: list[int]) -> None: ...

    def scores(self) -> np.ndarray:
        """The next-token logits after the last evaluated token."""


class SoloLane:
    """A llama_cpp.Llama's own context as a lane."""

    def __init__(self, llama) -> None:
        import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

        self.llama = llama
        self.size = llama_cpp.llama_vocab_n_tokens(llama._model.vocab)  # read once, not at every token

    @property
    def n_tokens(self) -> int:
        return self.llama.n_tokens

    @n_tokens.setter
    def n_tokens(self, count: int) -> None:
        self.llama.n_tokens = count

    def evaluate(self, tokens: list[int]) -> None:
        self.llama.eval(tokens)

    def scores(self) -> np.ndarray:
        import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

        return np.ctypeslib.as_array(llama_cpp.llama_get_logits_ith(self.llama._ctx.ctx, -1), shape=(self.size,))


def greedy_tokens(lane: Lane, vocab, grammar: str, prompt: list[int], max_tokens: int,
                  keep_going: Callable[[list[int]], bool],
                  forced: Callable[[list[int]], list[int]] | None = None) -> Iterator[int]:
    """Yield the tokens of the greedy completion of `prompt` that `grammar` admits, up to an end-of-generation
    token or `max_tokens`. Evaluation goes on from the tokens `lane` already holds (a shared prefix);
    `keep_going(tokens so far)` may end it after any token. The token that ends it is kept: one token can
    close a line and open the next (")\n"), and cutting it would leave the line unfinished. `forced(tokens so
    far)` may give the tokens that must follow (the grammar leaves one way to go on): they are evaluated in one
    batch, which costs about one token's time on a CPU, yielded, and the completion ends. `vocab` is the model's
    llama.cpp vocabulary."""
    import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

    sampler = llama_cpp.llama_sampler_init_grammar(vocab, grammar.encode(), b"root")
    if not sampler:
        raise GrammarRejected("llama.cpp could not parse the grammar")
    try:
        tail = prompt[lane.n_tokens:]
        if not tail:  # the whole prompt is already evaluated: replay its last token to get fresh scores
            lane.n_tokens -= 1
            tail = prompt[-1:]
        lane.evaluate(tail)
        generated: list[int] = []
        while len(generated) < max_tokens:
            token = _best_admitted(sampler, lane.scores())
            if token is None or llama_cpp.llama_vocab_is_eog(vocab, token):
                return
            llama_cpp.llama_sampler_accept(sampler, token)
            generated.append(token)
            yield token
            if not keep_going(generated):
                return
            rest = forced(generated) if forced is not None else []
            if rest and len(generated) + len(rest) <= max_tokens:
                lane.evaluate([token, *rest])
                yield from rest
                return
            lane.evaluate([token])
    finally:
        llama_cpp.llama_sampler_free(sampler)


def _best_admitted(sampler, scores: np.ndarray) -> int | None:
    """The highest-scoring token the grammar admits (the lowest id among equals, as llama.cpp's greedy
    sampler picks), or None when it admits none."""
    shortlist = np.sort(np.argpartition(scores, -SHORTLIST)[-SHORTLIST:])
    token = _admitted_argmax(sampler, scores, shortlist)
    return token if token is not None else _admitted_argmax(sampler, scores, np.arange(len(scores)))


def _admitted_argmax(sampler, scores: np.ndarray, ids: np.ndarray) -> int | None:
    import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

    data = np.zeros(len(ids), dtype=_TOKEN_DATA)
    data["id"] = ids
    data["logit"] = scores[ids]
    candidates = llama_cpp.llama_token_data_array(
        data=data.ctypes.data_as(llama_cpp.llama_token_data_p), size=len(data), selected=-1, sorted=False)
    llama_cpp.llama_sampler_apply(sampler, ctypes.byref(candidates))  # refused tokens get a logit of -inf
    best = int(np.argmax(data["logit"]))
    return int(ids[best]) if np.isfinite(data["logit"][best]) else None
