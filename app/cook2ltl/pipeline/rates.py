"""The two quality rates of one or more translations: the paper's executability (admissible model lines) and
the validated rate (new reductions whose plan ran in the kitchen)."""

from __future__ import annotations

from dataclasses import dataclass

from cook2ltl.domain.actions import Source
from cook2ltl.pipeline.records import Translation


@dataclass(frozen=True)
class Rates:
    """Counts behind the two quality rates of one or more translations."""

    written_lines: int  # plan lines the model wrote, repairs included
    admissible_lines: int  # of those, the ones kept: calls of the primitive set or the library
    new_reductions: int  # actions the model reduced
    validated: int | None  # of those, the ones whose plan passed the kitchen check (None: nothing validated)

    @property
    def executability(self) -> float | None:
        """The paper's executability: the share of the model's plan lines that are admissible."""
        return self.admissible_lines / self.written_lines if self.written_lines else None

    @property
    def validated_rate(self) -> float | None:
        """The stronger rate: the share of new reductions whose plan runs in the kitchen."""
        return self.validated / self.new_reductions if self.new_reductions and self.validated is not None else None


def rates(*translations: Translation) -> Rates:
    results = [r for t in translations for step in t.steps for r in step.actions if r.reduction.source == Source.LLM]
    outputs = [reduction for r in results for reduction in (*r.attempts, r.reduction)]
    passed = sum(1 for r in results if r.validation is not None and r.validation.passed)
    return Rates(sum(len(o.body) + len(o.dropped) for o in outputs), sum(len(o.body) for o in outputs),
                 len(results), passed if any(t.validating for t in translations) else None)
