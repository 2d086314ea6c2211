"""A scripted LanguageModel for unit tests: answers by the function header that ends the prompt."""

from __future__ import annotations

from dataclasses import dataclass, field

from cook2ltl.domain.actions import Usage
from cook2ltl.reduce.llm import Completion


@dataclass
class ScriptedModel:
    """`answers` maps a verb to the body it writes, or to the bodies it writes one after the other (the last
    one again once they run out); every prompt, static part and grammar it was given is kept."""

    answers: dict[str, str | list[str]]
    name: str = "scripted"
    prompts: list[str] = field(default_factory=list)
    statics: list[str] = field(default_factory=list)
    grammars: list[str] = field(default_factory=list)

    def complete(self, static: str, dynamic: str, grammar: str, max_tokens: int, stop=None) -> Completion:
        prompt = static + dynamic
        verb = _last_header(prompt).removeprefix("def ").split("(")[0]
        asked = sum(1 for earlier in self.prompts if _last_header(earlier).startswith(f"def {verb}("))
        self.prompts.append(prompt)
        self.statics.append(static)
        self.grammars.append(grammar)
        answer = self.answers.get(verb, "")
        lines = [line.strip() for line in (answer if isinstance(answer, str) else answer[min(asked, len(answer) - 1)])
                 .strip().splitlines()]
        # A repair prompt ends with the lines kept of the failed plan: like a model, go on after them.
        kept = [line.strip() for line in prompt.rsplit("\ndef ", 1)[-1].splitlines()[1:] if not line.strip().startswith("#")]
        if kept and lines[: len(kept)] == kept:
            lines = lines[len(kept):]
        text = "".join(f"    {line}\n" for line in lines) + "\n"
        return Completion(text, Usage(prompt_tokens=len(prompt.split()), completion_tokens=len(text.split()), seconds=0.01))

    def complete_lines(self, static: str, dynamic: str, next_lines, tokens_per_line: int) -> Completion:
        """Like a model under state-aware decoding: each scripted line the world allows is written, the others
        skipped; a blank line when none of the rest is allowed."""
        prompt = static + dynamic
        verb = _last_header(prompt).removeprefix("def ").split("(")[0]
        self.prompts.append(prompt)
        self.statics.append(static)
        answer = self.answers.get(verb, "")
        script = [line.strip() for line in (answer if isinstance(answer, str) else answer[0]).strip().splitlines()]
        text = ""
        while (options := next_lines(text)) is not None:
            self.grammars.append("\n".join(options))
            chosen = next((line for line in script if line in options), None)
            if chosen is None:
                break
            script = script[script.index(chosen) + 1:]
            text += f"    {chosen}\n"
        return Completion(text + "\n", Usage(prompt_tokens=len(prompt.split()), completion_tokens=len(text.split()),
                                             seconds=0.01))

    @property
    def calls(self) -> int:
        return len(self.prompts)


def _last_header(prompt: str) -> str:
    return next(line for line in reversed(prompt.splitlines()) if line.startswith("def "))
