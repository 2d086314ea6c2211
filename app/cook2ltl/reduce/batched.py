"""Several completions decoded together: one llama.cpp context, one sequence (lane) per completion, one batch per step.

Decoding on a CPU is bound by reading the weights, so a batch of four tokens from four sequences costs about
twice one token, not four times: translations running side by side (the bench's recipes, a batch of recipes)
share the model through `BatchedLlamaModel`, each from its own thread. A step is decoded when every open lane
waits for one, by the thread that asked last, so no thread of its own runs the model. The static part of the
prompts is evaluated once, in sequence 0, and shared by every lane's cache (llama.cpp's unified KV cache).

llama.cpp's arithmetic differs slightly with the batch a token is evaluated in, so a plan decoded in a batch
may differ from the one decoded alone; the greedy choice under the grammar is otherwise the same.
"""

from __future__ import annotations

import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import numpy as np

from cook2ltl.errors import UserError
from cook2ltl.reduce.llm import CONTEXT_TOKENS, DEFAULT_TIME_LIMIT, LlamaModel

STATIC = 0  # the sequence holding the prompts' static part
BATCH_TOKENS = 512  # tokens decoded in one llama_decode call


class BatchedLlamaModel(LlamaModel):
    """A LlamaModel that up to `lanes` threads may use at once, their completions decoded in one batch."""

    def __init__(self, name: str, path: Path, lanes: int, threads: int | None = None,
                 time_limit: float = DEFAULT_TIME_LIMIT) -> None:
        super().__init__(name, path, threads, None, time_limit)
        self.lanes = lanes
        self._steps: _Steps | None = None

    @contextmanager
    def _lane(self, static: str, prefix: list[int], deadline: float) -> Iterator[_BatchLane]:
        with self._loading:
            self._steps = self._steps or _Steps(self._llama, self.lanes, self.threads)
        lane = self._steps.open(prefix)
        try:
            yield lane
        finally:
            self._steps.close(lane)

    def close(self) -> None:
        if self._steps is not None:
            self._steps.free()
            self._steps = None


class _BatchLane:
    def __init__(self, steps: _Steps, sequence: int, n_tokens: int) -> None:
        self.steps, self.sequence, self.n_tokens = steps, sequence, n_tokens
        self._scores: np.ndarray | None = None

    def evaluate(self, tokens: list[int]) -> None:
        self._scores = self.steps.evaluate(self, tokens)
        self.n_tokens += len(tokens)

    def scores(self) -> np.ndarray:
        return self._scores


class _Steps:
    """The shared context and the step in progress: which lanes wait with which tokens."""

    def __init__(self, llama, lanes: int, threads: int) -> None:
        import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

        params = llama_cpp.llama_context_default_params()
        params.n_ctx = CONTEXT_TOKENS * 2  # the static part once, and each lane's own tokens
        params.n_batch = params.n_ubatch = BATCH_TOKENS
        params.n_seq_max = lanes + 1
        params.kv_unified = True  # lanes share the static part's cells
        params.n_threads = params.n_threads_batch = threads
        self.ctx = llama_cpp.llama_init_from_model(llama._model.model, params)
        if not self.ctx:
            raise UserError("llama.cpp could not make a context for batched decoding.", "run with one worker.")
        self.memory = llama_cpp.llama_get_memory(self.ctx)
        self.vocabulary = llama_cpp.llama_vocab_n_tokens(llama._model.vocab)
        self.batch = llama_cpp.llama_batch_init(BATCH_TOKENS, 0, 1)
        self.changed = threading.Condition()
        self.idle = list(range(lanes, STATIC, -1))
        self.open_lanes = 0
        self.static: list[int] = []
        self.waiting: dict[_BatchLane, list[int]] = {}
        self.scores: dict[_BatchLane, np.ndarray | Exception] = {}

    def open(self, prefix: list[int]) -> _BatchLane:
        import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

        with self.changed:
            self.changed.wait_for(lambda: self.idle)
            if prefix != self.static:  # lanes already open keep their copy of the old cells
                llama_cpp.llama_memory_seq_rm(self.memory, STATIC, -1, -1)
                self._decode({STATIC: (0, prefix)})
                self.static = prefix
            lane = _BatchLane(self, self.idle.pop(), len(prefix))
            llama_cpp.llama_memory_seq_cp(self.memory, STATIC, lane.sequence, -1, -1)
            self.open_lanes += 1
            return lane

    def close(self, lane: _BatchLane) -> None:
        import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

        with self.changed:
            llama_cpp.llama_memory_seq_rm(self.memory, lane.sequence, -1, -1)
            self.waiting.pop(lane, None)
            self.idle.append(lane.sequence)
            self.open_lanes -= 1
            self._step_if_all_wait()
            self.changed.notify_all()

    def evaluate(self, lane: _BatchLane, tokens: list[int]) -> np.ndarray:
        with self.changed:
            self.waiting[lane] = tokens
            self._step_if_all_wait()
            self.changed.wait_for(lambda: lane not in self.waiting)
            found = self.scores.pop(lane)
            if isinstance(found, Exception):
                raise found
            return found

    def _step_if_all_wait(self) -> None:
        if not self.waiting or len(self.waiting) < self.open_lanes:
            return
        try:
            found = self._decode({lane.sequence: (lane.n_tokens, tokens) for lane, tokens in self.waiting.items()})
            self.scores.update((lane, found[lane.sequence]) for lane in self.waiting)
        except Exception as error:  # every waiting lane's completion fails with it, not only the stepping one's
            self.scores.update((lane, error) for lane in self.waiting)
        finally:
            self.waiting.clear()
            self.changed.notify_all()

    def _decode(self, work: dict[int, tuple[int, list[int]]]) -> dict[int, np.ndarray]:
        """Evaluate each sequence's tokens from its position, BATCH_TOKENS at a time; each one's last scores."""
        import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

        queue = [(sequence, start + offset, token, offset == len(tokens) - 1)
                 for sequence, (start, tokens) in work.items() for offset, token in enumerate(tokens)]
        for sequence, (start, _) in work.items():  # what a lane evaluated past its position is stale
            llama_cpp.llama_memory_seq_rm(self.memory, sequence, start, -1)
        found: dict[int, np.ndarray] = {}
        for begin in range(0, len(queue), BATCH_TOKENS):
            chunk = queue[begin:begin + BATCH_TOKENS]
            batch = self.batch
            batch.n_tokens = len(chunk)
            for index, (sequence, position, token, last) in enumerate(chunk):
                batch.token[index], batch.pos[index], batch.logits[index] = token, position, last
                batch.n_seq_id[index], batch.seq_id[index][0] = 1, sequence
            if llama_cpp.llama_decode(self.ctx, batch) != 0:
                raise UserError("llama.cpp could not decode a batch: its context is full.", "run with fewer workers.")
            for index, (sequence, _, _, last) in enumerate(chunk):
                if last:
                    found[sequence] = np.ctypeslib.as_array(
                        llama_cpp.llama_get_logits_ith(self.ctx, index), shape=(self.vocabulary,)).copy()
        return found

    def free(self) -> None:
        import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

        llama_cpp.llama_batch_free(self.batch)
        llama_cpp.llama_free(self.ctx)
