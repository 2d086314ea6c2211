"""f_AR: one action reduced to admissible plan lines by a constrained model, and library verbs expanded."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Iterable, Sequence

from cook2ltl.domain.actions import Action, Call, PrimitiveSet, Reduction, Source
from cook2ltl.reduce.body import bind, instantiate, is_empty, loops, read_body, without_loops
from cook2ltl.reduce.grammar import admits, to_gbnf, unusable_verb, vocabulary
from cook2ltl.reduce.llm import LanguageModel
from cook2ltl.reduce.prompt import Feedback, build_prompt

TOKENS_PER_LINE = 40  # a call with its comment; the grammar ends the body long before this budget
MAX_DEPTH = 8  # library verbs calling library verbs; deeper means a cycle
MAX_PLAN = 60  # primitive calls of one expanded action; more means library verbs multiplying each other


@dataclass(frozen=True)
class ReductionSettings:
    max_lines: int = 12
    comments: bool = False  # the paper's comment lines: measured twice as slow for a small gain (README)


@dataclass(frozen=True)
class LibraryVerb:
    """A library entry as a callable for later prompts: `boil` with signature ("what",) and its body."""

    verb: str
    signature: tuple[str, ...]
    body: str


def offered_verbs(library: Iterable[LibraryVerb]) -> tuple[list[LibraryVerb], tuple[str, ...]]:
    """The library verbs a prompt and a grammar may offer the model, and why the others are not."""
    offered, reasons = [], {}
    for verb in library:
        reason = unusable_verb(verb.verb, verb.signature)
        if reason is None:
            offered.append(verb)
        else:
            reasons[reason] = None
    return offered, tuple(reasons)


def reduce_action(action: Action, primitives: PrimitiveSet, library: Sequence[LibraryVerb], model: LanguageModel,
                  settings: ReductionSettings, feedback: Feedback | None = None) -> Reduction:
    """Ask the model for the body of `action`; lines the grammar would not allow are dropped and kept aside.
    With `feedback` (a repair), the prompt says why the last plan failed, and the body goes on from the
    lines of it that are kept."""
    vocab = vocabulary(primitives, ((v.verb, v.signature) for v in library), action)
    prompt = build_prompt(primitives, (v.verb for v in library), action, settings.comments, feedback)
    kept = feedback.kept if feedback is not None else ()
    grammar = to_gbnf(vocab, settings.max_lines - len(kept), settings.comments, feedback.avoid if feedback else ())
    completion = model.complete(prompt.static, prompt.dynamic, grammar, settings.max_lines * TOKENS_PER_LINE, loops)
    calls, unread = read_body(completion.text)
    calls = without_loops(kept + calls)
    kept = tuple(call for call in calls if admits(vocab, call))[: settings.max_lines]
    dropped = unread + tuple(call.text() for call in calls if not admits(vocab, call))
    return Reduction(action, kept, Source.LLM, completion.usage, dropped, prompt.digest)


def expand(calls: Sequence[Call], primitives: PrimitiveSet, find: Callable[[str, int], LibraryVerb | None],
           depth: int = 0) -> tuple[Call, ...] | None:
    """Library verbs in a body replaced by their own bodies, down to primitives; None if something cannot be
    (an unknown verb, a cycle, a plan longer than MAX_PLAN)."""
    if depth > MAX_DEPTH:
        return None
    expanded: list[Call] = []
    for call in calls:
        if primitives.get(call.name) is not None:
            expanded.append(call)
            continue
        verb = find(call.name, len(call.args))
        callable_ = verb is not None and not is_empty(verb.body)  # an entry without a plan is no verb to call
        inner = instantiate(verb.body, bind(verb.signature, call.args)) if callable_ else None
        inner = expand(inner, primitives, find, depth + 1) if inner is not None else None
        if inner is None:
            return None
        expanded.extend(inner)
    return tuple(expanded) if len(expanded) <= MAX_PLAN else None
