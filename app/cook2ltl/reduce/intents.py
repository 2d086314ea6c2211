"""Where each action's intended effect comes from: the library entry's own, else the verb-effect table's,
else the model's (`effect_writer`), asked once per verb and signature in a run and then kept with the entry."""

from __future__ import annotations

from collections.abc import Sequence

from cook2ltl.domain.actions import Action, Usage
from cook2ltl.reduce.effect_writer import write_effect
from cook2ltl.reduce.llm import LanguageModel
from cook2ltl.world.effects import Template, intended_effect, parse_template, table_effect, verb_table
from cook2ltl.world.logic import Fact, State
from cook2ltl.world.world import World


class Intents:
    def __init__(self, world: World, model: LanguageModel | None) -> None:
        self.world = world
        self.model = model  # None: a verb the table lacks has no effect (nothing is asked)
        self._known: dict[tuple[str, tuple[str, ...]], tuple[Template, ...]] = {}
        self.written: list[Usage] = []  # one per effect the model wrote

    def templates(self, action: Action, state: State, stored: Sequence[str] | None = None,
                  write: bool = True) -> tuple[Template, ...]:
        """`write`: whether the model may be asked (not for a primitive the recipe names itself)."""
        if stored is not None:
            return tuple(parse_template(text) for text in stored)
        key = (action.verb, action.signature)
        if key not in self._known:
            known = table_effect(action.verb)
            if known is None and not (write and self.model is not None):
                return ()
            if known is None:
                known, usage = write_effect(action, self.model, self.world, state, verb_table())
                self.written.append(usage)
            self._known[key] = known or ()
        return self._known[key]

    def facts(self, action: Action, state: State, stored: Sequence[str] | None = None,
              write: bool = True) -> tuple[Fact, ...]:
        """The facts the action must make true where it is used."""
        return intended_effect(action, self.world, state, self.templates(action, state, stored, write)) or ()
