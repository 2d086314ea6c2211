"""State-aware decoding: the model writes a plan line by line, each line chosen among those the world allows.

Before every line the grammar admits only the calls that can be applied in the state the lines so far
reached, from where the recipe had got to (`world.affordances`). Once the action's intended effect holds,
only lines that tidy up and keep it are admitted (turning the microwave off, closing the fridge; not taking
the apple out again), until the model ends the body or there are none; what it leaves undone the planner
completes (`world.check`).
"""

from __future__ import annotations

from collections.abc import Sequence

from cook2ltl.domain.actions import Action, PrimitiveSet, Reduction, Source
from cook2ltl.reduce.body import read_body
from cook2ltl.reduce.grammar import vocabulary
from cook2ltl.reduce.llm import LanguageModel
from cook2ltl.reduce.prompt import build_prompt
from cook2ltl.reduce.reduction import TOKENS_PER_LINE, ReductionSettings
from cook2ltl.world.affordances import admissible_calls
from cook2ltl.world.logic import Fact, State
from cook2ltl.world.planner import all_reached
from cook2ltl.world.world import World

REPEATS = 2  # the same line this many times in a row ends the plan: a greedy model is looping


def reduce_in_world(action: Action, primitives: PrimitiveSet, library_verbs: Sequence[str], model: LanguageModel,
                    settings: ReductionSettings, world: World, state: State, effect: Sequence[Fact]) -> Reduction:
    vocab = vocabulary(primitives, (), action)
    prompt = build_prompt(primitives, library_verbs, action, comments=False)

    applied: list = []  # the lines applied so far, and the state they reached: each line is applied once
    now = state

    def next_lines(text: str) -> list[str] | None:
        nonlocal now
        calls, _ = read_body(text)
        if len(calls) >= settings.max_lines or _looping(calls):
            return None
        if calls[:len(applied)] != applied:  # the text was not just extended: start from the action's state
            applied.clear()
            now = state
        for call in calls[len(applied):]:
            now = world.apply(now, call).state
            applied.append(call)
        options = admissible_calls(world, now, primitives, vocab.objects, vocab.states, vocab.durations)
        if effect and all_reached(now, effect):  # only tidying up now: lines that undo a change, keeping the effect
            changed = len(now.facts ^ state.facts)
            options = [call for call in options if _tidies(world.apply(now, call).state, state, changed, effect)]
        return [call.text() for call in options] or None

    completion = model.complete_lines(prompt.static, prompt.dynamic, next_lines, TOKENS_PER_LINE)
    calls, unread = read_body(completion.text)
    return Reduction(action, calls, Source.LLM, completion.usage, unread, prompt.digest)


def _tidies(after: State, start: State, changed: int, effect: Sequence[Fact]) -> bool:
    """Whether a line brings the kitchen back towards where the action found it (turns off what the plan turned
    on, closes what it opened) and keeps the effect."""
    return len(after.facts ^ start.facts) < changed and all_reached(after, effect)



def _looping(calls) -> bool:
    return len(calls) >= REPEATS and len(set(calls[-REPEATS:])) == 1
