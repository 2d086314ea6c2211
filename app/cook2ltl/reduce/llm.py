"""The language model behind action reduction: a small Protocol, and llama.cpp as the backend.

llama_cpp is imported only when the first completion is asked for, so importing this module is instant
and a run that finds every action in the library never loads a model.
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

from cook2ltl.errors import UserError
from cook2ltl.reduce.model import Usage

DEFAULT_MODEL = "qwen2.5-coder-1.5b"  # chosen by measurement: see the README's "Action reduction"
SEED = 4242
CONTEXT_TOKENS = 4096


@dataclass(frozen=True)
class Completion:
    text: str
    usage: Usage


class LanguageModel(Protocol):
    """Completes a prompt under a GBNF grammar, deterministically."""

    name: str

    def complete(self, prompt: str, grammar: str, max_tokens: int) -> Completion: ...


class LlamaModel:
    """A GGUF model run by llama-cpp-python at temperature 0 with a fixed seed.

    llama-cpp-python keeps the tokens it last evaluated and re-evaluates only from the first token
    that differs, so prompts that share their static prefix cost only their dynamic tail.
    """

    def __init__(self, name: str, path: Path, seed: int = SEED, threads: int | None = None) -> None:
        self.name = name
        self.path = path
        self.seed = seed
        self.threads = threads or os.cpu_count() or 1
        self._llama = None

    def complete(self, prompt: str, grammar: str, max_tokens: int) -> Completion:
        llama = self._loaded()
        from llama_cpp import LlamaGrammar

        started = time.perf_counter()
        try:
            compiled = LlamaGrammar.from_string(grammar, verbose=False)
        except ValueError as error:
            raise UserError(f"llama.cpp rejected the generated grammar: {error}",
                            "check the names in the primitive set file; they must be plain identifiers.") from error
        result = llama.create_completion(
            prompt, max_tokens=max_tokens, temperature=0.0, seed=self.seed, grammar=compiled,
            repeat_penalty=1.0,  # plans rightly repeat objects (pot, pot, pot); a penalty would push them out
        )
        usage = result["usage"]
        return Completion(
            result["choices"][0]["text"],
            Usage(usage["prompt_tokens"], usage["completion_tokens"], time.perf_counter() - started),
        )

    def _loaded(self):
        if self._llama is None:
            from cook2ltl import offline

            offline.enforce()  # sets OMP_WAIT_POLICY before llama.cpp starts its threads
            try:
                from llama_cpp import Llama
            except ImportError as error:
                raise UserError("llama-cpp-python is not installed.", "install the `llm` extra: pip install -e '.[llm]'.") from error
            self._llama = Llama(model_path=str(self.path), n_ctx=CONTEXT_TOKENS, n_threads=self.threads,
                                seed=self.seed, verbose=False)
        return self._llama


def load_model(name: str = DEFAULT_MODEL) -> LlamaModel:
    """A GGUF model of the manifest by name; it is read from disk at its first completion."""
    from cook2ltl.models.manifest import State, load_manifest, model_path, state_of

    manifest = load_manifest()
    choices = [entry.name for entry in manifest.values() if entry.file.endswith(".gguf")]
    entry = manifest.get(name)
    if entry is None or name not in choices:
        raise UserError(f"No language model {name!r} in the model manifest.", f"choose one of: {', '.join(choices)}.")
    if state_of(entry, verify_hash=False) != State.READY:
        raise UserError(f"The model {name!r} is not provisioned.", "run `make models` (or `cook2ltl models provision`).")
    return LlamaModel(name, model_path(entry))
