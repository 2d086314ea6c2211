"""A task's instruction planned by Algorithm 1 with the AI2-THOR primitives: the formula a rollout executes.

A thin adapter over `cook2ltl.pipeline.translator`: parse the instruction, reduce its
actions (primitive, library or model), keep the whole formula and the plan
lines for display. `open_planner` builds the production backends (GLiNER,
spaCy, llama.cpp, the SQLite library) once, so a benchmark plans many times.
"""

from __future__ import annotations

import time
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from pathlib import Path

from cook2ltl.assembly import backends
from cook2ltl.assembly.translators import TranslateOptions, open_translator
from cook2ltl.domain.actions import Call
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.ltl.ast import Formula
from cook2ltl.parse.backends import DependencyParser, SpanExtractor
from cook2ltl.pipeline.records import Stats, TranslationFinished, Variant
from cook2ltl.pipeline.translator import Translator, run
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.world.kitchens import grounding

PRIMITIVES = "ai2thor"


@dataclass(frozen=True)
class Plan:
    instruction: str
    formula: Formula
    calls: tuple[Call, ...]  # every action's primitive plan, in order
    sources: tuple[str, ...]  # per action: primitive, library or llm
    problems: tuple[str, ...]
    model: str
    variant: Variant
    stats: Stats
    seconds: float
    binding: Mapping[str, str] = field(default_factory=dict)  # the objectId each name stands for (world model)


@dataclass(frozen=True)
class TaskPlanner:
    translator: Translator
    spans: SpanExtractor
    dependencies: DependencyParser
    ground: bool = True  # check and complete every plan in the world model of the kitchen it will run in

    def plan(self, instruction: str, scene: str | None = None, objects: Sequence[Mapping] | None = None) -> Plan:
        """Plan the instruction for the kitchen `scene`, or the running kitchen whose metadata is `objects`."""
        started = time.perf_counter()
        translator = self.translator
        if self.ground:
            supply = (lambda: objects) if objects is not None else None
            translator = replace(translator, grounding=grounding(translator.primitives, scene=scene, objects=supply))
        events = run(instruction, self.spans, self.dependencies, translator)
        translation = next(e.translation for e in events if isinstance(e, TranslationFinished))
        results = [result for step in translation.steps for result in step.actions]
        return Plan(
            instruction,
            translation.formula,
            tuple(call for result in results for call in result.plan),
            tuple(result.reduction.source.value for result in results),
            tuple(problem for step in translation.steps for problem in step.problems),
            translation.model,
            translation.variant,
            translation.stats,
            time.perf_counter() - started,
            translation.world_binding,
        )


@contextmanager
def open_planner(model: str, library: Path | None, variant: Variant = Variant.AR_LIBRARY, validate: bool = True,
                 repairs: int = 2, ground: bool = True) -> Iterator[TaskPlanner]:
    """The production planner; the library file (default: the user's) and the kitchen that checks new
    reductions before they are cached (AR+A with `validate`, as `cook2ltl translate`) are closed on exit."""
    # The planner grounds each plan in the kitchen it will run in, so the translator itself has no world.
    options = TranslateOptions(variant, check=None if validate else False, repairs=repairs, ground=False)
    with open_translator(load_primitives(PRIMITIVES), backends.load_model(model), library, options,
                         ignore_notice) as translator:
        yield TaskPlanner(translator, backends.span_extractor(load_settings()), backends.dependency_parser(), ground)


def ignore_notice(notice: str) -> None:
    """The AI2-THOR set is the kitchen's own: every action runs there, so no notice about checks can arise."""


def plan_json(plan: Plan) -> dict:
    return {
        "instruction": plan.instruction,
        "model": plan.model,
        "variant": plan.variant.value,
        "calls": [call.text() for call in plan.calls],
        "sources": list(plan.sources),
        "problems": list(plan.problems),
        "llm_calls": plan.stats.llm_calls,
        "library_hits": plan.stats.library_hits,
        "seconds": round(plan.seconds, 3),
    }
