"""The canonical order of formulas, in which ∧ and ∨ keep their operands.

The order is lexicographic on (rank, operands…): constants, then atoms by name
and arguments, then the operators by rank (see :mod:`cook2ltl.ltl.ast`), each
by its operands in turn; of two ∧ (or ∨) whose operands start alike, the one
with fewer comes first. It is compared with a loop, so any depth is fine.
"""

from __future__ import annotations

from functools import cmp_to_key
from typing import TYPE_CHECKING

from cook2ltl.ltl.limits import charge

if TYPE_CHECKING:
    from cook2ltl.ltl.ast import Formula


def compare(x: Formula, y: Formula) -> int:
    """-1, 0 or 1 as ``x`` sorts before, with or after ``y``."""
    walked: list[tuple[Formula, Formula]] = []
    answer = _first_difference(x, y, walked)
    if len(_COMPARED) + len(walked) > _COMPARED_ENTRIES:
        _COMPARED.clear()
    for pair in walked:
        _COMPARED[pair] = answer
    return answer


SORT_KEY = cmp_to_key(compare)

# The answers for pairs of operators compare() walked through, so formulas
# built level by level (as progression builds them) compare in one step.
_COMPARED: dict[tuple[Formula, Formula], int] = {}
_COMPARED_ENTRIES = 1 << 16


def clear_compared() -> None:
    _COMPARED.clear()


def _first_difference(x: Formula, y: Formula, walked: list[tuple[Formula, Formula]]) -> int:
    """compare() with a loop. Equal subformulas are one object, so it goes down
    a single path to the first pair that differ, and that pair's answer is the
    answer of every pair it walked through (``walked``)."""
    pairs: list = [(x, y)]
    while pairs:
        a, b = pairs.pop()
        if isinstance(a, int):  # operand counts, once the operands they share are equal
            if a != b:
                return -1 if a < b else 1
            continue
        if a is b:
            continue
        if a.rank != b.rank:
            return -1 if a.rank < b.rank else 1
        mine, theirs = a.constructor_args(), b.constructor_args()
        if a.rank < 2:  # a constant (its value) or an atom (name, then arguments)
            return -1 if mine < theirs else 1
        known = _COMPARED.get((a, b))
        if known is not None:
            return known
        walked.append((a, b))
        charge()
        pairs.append((len(mine), len(theirs)))
        pairs.extend(reversed(list(zip(mine, theirs))))
    return 0
