"""State-aware decoding: the model writes a plan line by line, each line chosen among those the world allows.

Before every line the grammar admits only the calls that can be applied in the state the lines so far
reached, from where the recipe had got to (`world.affordances`). Once the action's intended effect holds,
only lines that tidy up and keep it are admitted (turning the microwave off, closing the fridge; not taking
the apple out again), until the model ends the body or there are none; what it leaves undone the planner
completes (`world.check`).
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import replace

from cook2ltl.domain.actions import Action, Call, PrimitiveSet, Reduction, Source
from cook2ltl.reduce.body import read_body
from cook2ltl.reduce.grammar import vocabulary
from cook2ltl.reduce.llm import LanguageModel
from cook2ltl.reduce.prompt import build_prompt
from cook2ltl.reduce.reduction import TOKENS_PER_LINE, ReductionSettings
from cook2ltl.world.affordances import admissible_calls
from cook2ltl.world.check import Grounding
from cook2ltl.world.logic import Fact, State
from cook2ltl.world.planner import HOLDING, all_reached
from cook2ltl.world.world import World

SLACK = 3  # lines a model's plan may take beyond the planner's way: more is wandering, and the planner completes


def reduce_in_world(action: Action, primitives: PrimitiveSet, model: LanguageModel, settings: ReductionSettings,
                    grounding: Grounding, state: State, effect: Sequence[Fact]) -> Reduction:
    world = grounding.world
    vocab = vocabulary(primitives, (), action)
    started = time.perf_counter()
    objects, most_lines = _focus(vocab.objects, action, grounding, state, effect, settings.max_lines)
    planning = time.perf_counter() - started
    # No library verbs: the line grammar offers primitives only, so listing them would be read for nothing.
    prompt = build_prompt(primitives, (), action, comments=False)

    def next_lines(text: str) -> list[str] | None:
        written, _ = read_body(text)
        calls, went_through = _path(world, state, written, bool(effect))
        if len(calls) < len(written) or len(calls) >= most_lines or _repeats(calls):
            return None  # the model went back to where it had been (it is looping), or wrote all a plan may take
        now = went_through[-1]
        options = admissible_calls(world, now, primitives, objects, vocab.states, vocab.durations)
        if effect and all_reached(now, effect):  # only tidying up now: lines that undo a change, keeping the effect
            changed = len(now.facts ^ state.facts)
            options = [call for call in options if _tidies(world.apply(now, call).state, state, changed, effect)]
        return [call.text() for call in options] or None

    completion = model.complete_lines(prompt.static, prompt.dynamic, next_lines, TOKENS_PER_LINE)
    calls, unread = read_body(completion.text)
    usage = replace(completion.usage, choice_seconds=completion.usage.choice_seconds + planning)  # the world's time
    return Reduction(action, _path(world, state, calls, bool(effect))[0], Source.LLM, usage, unread, prompt.digest)


def _path(world: World, state: State, calls: Sequence[Call], detours: bool) -> tuple[tuple[Call, ...], list[State]]:
    """The lines, up to the first that brings the kitchen back to a state the plan has been in (a detour, a
    loop, a line that changes nothing) with `detours`, and the states they go through. Without an effect to
    reach, progress cannot be told: only a line written twice in a row ends the plan (`_repeats`)."""
    went_through = [state]
    for count, call in enumerate(calls):
        after = world.apply(went_through[-1], call).state
        if detours and any(after.facts == visited.facts for visited in went_through):
            return tuple(calls[:count]), went_through
        went_through.append(after)
    return tuple(calls), went_through


def _focus(objects: Sequence[str], action: Action, grounding: Grounding, state: State, effect: Sequence[Fact],
           max_lines: int) -> tuple[Sequence[str], int]:
    """The objects a line may name, and how many lines a plan may take. When the planner knows a way to the
    effect: the action's own objects, the effect's, what is in hand, the kitchen's everyday things for this
    effect (the planner's kit) and whatever that way uses, in at most SLACK lines more than it takes. A line
    about anything else (switching the toaster on to boil pasta) is wandering the world model can tell. Without
    an effect, a kit or a way: every object, `max_lines` lines."""
    planner = grounding.planner
    kit = planner.kit_for(effect) if effect and planner is not None else None
    way = planner.plan(grounding.world, state, effect) if kit is not None else None
    if way is None:
        return objects, max_lines
    wanted = {*action.objects, *(arg for fact in effect for arg in fact[1:]), *kit,
              *(arg for call in way for arg in call.args), *(fact[1] for fact in state.by_predicate.get(HOLDING, ()))}
    return [name for name in objects if name in wanted], min(max_lines, len(way) + SLACK)


def _tidies(after: State, start: State, changed: int, effect: Sequence[Fact]) -> bool:
    """Whether a line brings the kitchen back towards where the action found it (turns off what the plan turned
    on, closes what it opened) and keeps the effect."""
    return len(after.facts ^ start.facts) < changed and all_reached(after, effect)


def _repeats(calls: Sequence[Call]) -> bool:
    return len(calls) >= 2 and calls[-1] == calls[-2]
