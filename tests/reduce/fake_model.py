"""A scripted LanguageModel for unit tests: answers by the function header that ends the prompt."""

from __future__ import annotations

from dataclasses import dataclass, field

from cook2ltl.reduce.llm import Completion
from cook2ltl.reduce.model import Usage


@dataclass
class ScriptedModel:
    """`answers` maps a verb to the body it writes; every prompt and grammar it was given is kept."""

    answers: dict[str, str]
    name: str = "scripted"
    prompts: list[str] = field(default_factory=list)
    grammars: list[str] = field(default_factory=list)

    def complete(self, static: str, dynamic: str, grammar: str, max_tokens: int, stop=None) -> Completion:
        prompt = static + dynamic
        self.prompts.append(prompt)
        self.grammars.append(grammar)
        verb = prompt.rstrip().splitlines()[-1].removeprefix("def ").split("(")[0]
        body = self.answers.get(verb, "")
        text = "".join(f"    {line.strip()}\n" for line in body.strip().splitlines()) + "\n"
        return Completion(text, Usage(prompt_tokens=len(prompt.split()), completion_tokens=len(text.split()), seconds=0.01))

    @property
    def calls(self) -> int:
        return len(self.prompts)
