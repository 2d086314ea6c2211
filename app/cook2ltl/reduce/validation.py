"""What checking a plan reports, line by line, and the protocol every plan checker meets.

The reduction stage repairs a plan from these reports and the library keeps them; the robot side
(`execution.kitchen_check`) makes them by running the plan in a kitchen."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from enum import StrEnum
from typing import Protocol

from cook2ltl.domain.actions import Action, Call


class CheckStatus(StrEnum):
    """A plan's kitchen check, as the library keeps it beside the body it checked."""

    PASSED = "passed"
    FAILED = "failed"
    UNCHECKED = "unchecked"  # never run: nothing in the kitchen could stand for an object, or no check was asked
@dataclass(frozen=True)
class LineProblem:
    line: int  # 1-based in the plan; 0 for the whole plan
    call: str
    message: str

    def text(self) -> str:
        return f"line {self.line} {self.call}: {self.message}" if self.line else f"{self.call}: {self.message}"


@dataclass(frozen=True)
class Validation:
    passed: bool
    problems: tuple[LineProblem, ...]
    scene: str
    seconds: float
    checked: bool = True  # False when the kitchen has nothing that can stand for an object of the plan

    def messages(self) -> tuple[str, ...]:
        return tuple(problem.text() for problem in self.problems)

    @property
    def status(self) -> CheckStatus:
        """The library's `validation` column."""
        if not self.checked:
            return CheckStatus.UNCHECKED
        return CheckStatus.PASSED if self.passed else CheckStatus.FAILED


@dataclass(frozen=True)
class RecipeSoFar:
    """Where a recipe has got to in a THOR kitchen: the scene, the object each name stands for, and the lines
    its earlier actions ran. A plan checked here runs after them, as it will in the recipe."""

    scene: str
    binding: Mapping[str, str]
    before: tuple[Call, ...] = ()


class PlanValidator(Protocol):
    def validate(self, action: Action, plan: tuple[Call, ...], so_far: RecipeSoFar | None = None) -> Validation: ...

    def close(self) -> None: ...
