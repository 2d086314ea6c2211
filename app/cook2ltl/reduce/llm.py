"""The language model behind action reduction: a small Protocol, and llama.cpp as the backend.

llama_cpp is imported only when the first completion is asked for, so importing this module is instant
and a run that finds every action in the library never loads a model.

A completion is bounded in tokens (the caller's `max_tokens`) and in time (`time_limit`), and stops at once
when the model's `cancel` event is set; a stopped completion raises instead of returning half a plan, so
nothing cut short is ever cached in the library.
"""

from __future__ import annotations

import ctypes
import hashlib
import os
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from collections.abc import Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Callable, Protocol

from cook2ltl import offline
from cook2ltl.domain.actions import Usage
from cook2ltl.domain.settings import Limits
from cook2ltl.errors import UserError
from cook2ltl.reduce.grammar import gbnf_literal

if TYPE_CHECKING:
    from cook2ltl.reduce.decoding import Lane

CONTEXT_TOKENS = 4096
DEFAULT_TIME_LIMIT = Limits.llm_seconds  # seconds; load_model takes the settings' [limits] llm_seconds


class GenerationStopped(UserError):
    """A completion ran past its time limit."""


class GenerationCancelled(GenerationStopped):
    """A completion was cancelled through the model's `cancel` event (a UI's cancel button)."""


@dataclass(frozen=True)
class Completion:
    text: str
    usage: Usage


class LanguageModel(Protocol):
    """Completes `static + dynamic` under a GBNF grammar, deterministically.

    `static` is the part many prompts share (a backend may keep it evaluated); `dynamic` is this prompt's own.
    `stop`, given the text generated so far, may end the completion early.
    """

    name: str

    def complete(self, static: str, dynamic: str, grammar: str, max_tokens: int,
                 stop: Callable[[str], bool] | None = None) -> Completion: ...

    def complete_lines(self, static: str, dynamic: str, next_lines: Callable[[str], list[str] | None],
                       tokens_per_line: int) -> Completion:
        """Write indented lines one at a time, each one of `next_lines(text so far)` (or a blank line that
        ends the body), until `next_lines` gives None."""


def line_grammar(options: list[str]) -> str:
    """One line: an indented call among `options`, or a blank line (the body ends)."""
    calls = " | ".join(gbnf_literal(option) for option in options)
    return f'root ::= "    " call "\\n" | "\\n"\ncall ::= {calls}\n'


class LlamaModel:
    """A GGUF model run by llama-cpp-python, decoding greedily under the grammar (cook2ltl.reduce.decoding).

    The static part is always evaluated on its own and kept: later prompts evaluate only their dynamic
    tail. Evaluating it the same way every time also keeps results independent of what was reduced before
    (llama.cpp's arithmetic differs slightly with the batch a token is evaluated in). With a `state_dir`,
    the evaluated static part is saved to disk and restored by later processes.
    """

    def __init__(self, name: str, path: Path, threads: int | None = None,
                 state_dir: Path | None = None, time_limit: float = DEFAULT_TIME_LIMIT) -> None:
        self.name = name
        self.path = path
        self.threads = threads or os.cpu_count() or 1
        self.state_dir = state_dir
        self.restored = False  # whether the last static part came from disk
        self.time_limit = time_limit
        self.cancel = threading.Event()  # a caller may replace it with its own job's event
        self._llama = None
        self._loading = threading.Lock()

    def complete(self, static: str, dynamic: str, grammar: str, max_tokens: int,
                 stop: Callable[[str], bool] | None = None) -> Completion:
        llama = self._loaded()
        # heavy: numpy (~150 ms) loads with the first completion
        from cook2ltl.reduce.decoding import GrammarRejected, greedy_tokens

        started = time.perf_counter()
        # Tokenised apart, so the static tokens never depend on what follows them.
        prefix = llama.tokenize(static.encode())
        tokens = prefix + llama.tokenize(dynamic.encode(), add_bos=False)
        room = llama.n_ctx() - len(tokens)
        if room <= 0:
            raise UserError(f"The prompt has {len(tokens)} tokens, more than the model's context of {llama.n_ctx()}.",
                            "shorten the step, or review the library: every verb in it is listed in the prompt.")
        deadline = started + self.time_limit
        self._check(deadline)

        def keep_going(ids: list[int]) -> bool:
            if self.cancel.is_set() or time.perf_counter() > deadline:
                return False
            return stop is None or not stop(self._text(ids))

        generated: list[int] = []
        prompt_seconds = 0.0
        try:
            with self._lane(static, prefix, deadline) as lane:
                for token in greedy_tokens(lane, llama._model.vocab, grammar, tokens, min(max_tokens, room), keep_going):
                    # the first token comes once the prompt is evaluated (its tail beyond the cached static part)
                    prompt_seconds = prompt_seconds or time.perf_counter() - started
                    generated.append(token)
        except GrammarRejected as error:
            hint = "every word in it is escaped, so this is a bug in cook2ltl: please report it with the recipe."
            raise UserError("llama.cpp rejected the generated grammar.", hint) from error
        self._check(deadline)
        seconds = time.perf_counter() - started
        return Completion(self._text(generated),
                          Usage(len(tokens), len(generated), seconds, prompt_seconds or seconds))

    def complete_lines(self, static: str, dynamic: str, next_lines: Callable[[str], list[str] | None],
                       tokens_per_line: int) -> Completion:
        llama = self._loaded()
        started = time.perf_counter()
        prefix = llama.tokenize(static.encode())
        tokens = prefix + llama.tokenize(dynamic.encode(), add_bos=False)
        deadline = started + self.time_limit
        self._check(deadline)
        with self._lane(static, prefix, deadline) as lane:
            return self._lines(lane, tokens, next_lines, tokens_per_line, started, deadline)

    def _lines(self, lane: Lane, tokens: list[int], next_lines: Callable[[str], list[str] | None], tokens_per_line: int,
               started: float, deadline: float) -> Completion:
        from cook2ltl.reduce.decoding import greedy_tokens  # heavy: numpy (~150 ms) loads with the first completion

        llama = self._llama
        generated: list[int] = []
        text = ""
        choosing = prompt_seconds = 0.0  # the caller's time choosing lines is not the model's

        def line_open(ids: list[int]) -> bool:
            return not (self.cancel.is_set() or time.perf_counter() > deadline or self._text(ids).endswith("\n"))

        while len(tokens) + len(generated) + tokens_per_line < llama.n_ctx():
            chose = time.perf_counter()
            options = next_lines(text)
            choosing += time.perf_counter() - chose
            if not options:
                break
            line: list[int] = []
            lines = ("\n", *(f"    {option}\n" for option in options))

            def forced(ids: list[int], lines: tuple[str, ...] = lines) -> list[int]:
                """The rest of the line, once only one of the options can follow what is written."""
                written = self._text(ids)
                possible = [candidate for candidate in lines if candidate.startswith(written)]
                if len(possible) != 1 or len(possible[0]) == len(written):
                    return []
                return llama.tokenize(possible[0][len(written):].encode(), add_bos=False)

            for token in greedy_tokens(lane, llama._model.vocab, line_grammar(options), tokens + generated,
                                       tokens_per_line, line_open, forced):
                prompt_seconds = prompt_seconds or time.perf_counter() - started - choosing
                line.append(token)
            self._check(deadline)
            generated += line
            text = self._text(generated)
            if not line or not text.endswith("\n") or text.endswith("\n\n") or text == "\n":
                break  # a blank line: the model ended the body
        seconds = time.perf_counter() - started - choosing
        return Completion(text, Usage(len(tokens), len(generated), seconds, prompt_seconds or seconds, choosing))

    @contextmanager
    def _lane(self, static: str, prefix: list[int], deadline: float) -> Iterator[Lane]:
        """The lane a completion decodes in, holding the evaluated static part: this model's own context."""
        from cook2ltl.reduce.decoding import SoloLane  # heavy: numpy (~150 ms) loads with the first completion

        self._keep_only(self._llama, prefix, static, deadline)
        yield SoloLane(self._llama)

    def _text(self, ids: list[int]) -> str:
        return self._llama.detokenize(ids).decode("utf-8", errors="ignore")

    def _check(self, deadline: float) -> None:
        if self.cancel.is_set():
            raise GenerationCancelled(f"Cancelled while {self.name} was writing a plan.")
        if time.perf_counter() > deadline:
            raise GenerationStopped(f"{self.name} took more than {self.time_limit:g} s on one reduction; stopped.",
                                    "raise [limits] llm_seconds in the settings file, or choose a faster --model.")

    def _keep_only(self, llama, prefix: list[int], static: str, deadline: float) -> None:
        """Leave exactly the static part evaluated: from memory, from disk, or evaluated now and saved."""
        self.restored = False
        count = len(prefix)
        if llama.n_tokens >= count and llama.input_ids[:count].tolist() == prefix:
            llama.n_tokens = count  # llama-cpp-python evaluates the rest of the prompt from here
            return
        path = self._state_file(static)
        if path is not None and path.is_file() and self._restore(llama, path, prefix):
            self.restored = True
            return
        llama.reset()
        # Batch by batch, as eval() would split it, so a long cold prefix can be cancelled part-way.
        for begin in range(0, count, llama.n_batch):
            self._check(deadline)
            llama.eval(prefix[begin:begin + llama.n_batch])
        if path is not None:
            self._save(llama, path)

    def _state_file(self, static: str) -> Path | None:
        if self.state_dir is None:
            return None
        import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

        # Valid for this model file, static part, context size and llama.cpp build only.
        key = hashlib.sha256(f"{self.path.stat().st_size}|{CONTEXT_TOKENS}|{llama_cpp.__version__}|{static}".encode())
        return self.state_dir / f"{self.name}-{key.hexdigest()[:16]}.state"

    def _restore(self, llama, path: Path, prefix: list[int]) -> bool:
        import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

        tokens = (llama_cpp.llama_token * CONTEXT_TOKENS)()
        count = ctypes.c_size_t(0)
        loaded = llama_cpp.llama_state_load_file(llama._ctx.ctx, str(path).encode(), tokens, CONTEXT_TOKENS,
                                                 ctypes.byref(count))
        if not loaded or list(tokens[: count.value]) != prefix:
            llama.reset()  # a stale or damaged file is ignored and overwritten
            return False
        llama.input_ids[: len(prefix)] = prefix
        llama.n_tokens = len(prefix)
        return True

    def _save(self, llama, path: Path) -> None:
        import llama_cpp  # heavy, optional: llama.cpp (the llm extra) loads with the model

        path.parent.mkdir(parents=True, exist_ok=True)
        partial = path.with_suffix(".partial")
        tokens = (llama_cpp.llama_token * llama.n_tokens)(*llama.input_ids[: llama.n_tokens].tolist())
        if llama_cpp.llama_state_save_file(llama._ctx.ctx, str(partial).encode(), tokens, llama.n_tokens):
            partial.replace(path)  # never a half-written state under the final name

    def _loaded(self):
        with self._loading:  # threads sharing a batched model ask for it at once; it is loaded once
            return self._llama or self._load()

    def _load(self):
        offline.enforce()  # sets GOMP_SPINCOUNT before llama.cpp starts its threads
        try:
            from llama_cpp import Llama  # heavy, optional: loaded with the model, after offline.enforce()
        except ImportError as error:
            raise UserError("llama-cpp-python is not installed.", "install the `llm` extra: pip install -e '.[llm]'.") from error
        self._llama = Llama(model_path=str(self.path), n_ctx=CONTEXT_TOKENS, n_threads=self.threads, verbose=False)
        return self._llama
