"""Check a formula's atoms against the robot's primitives.

The primitives are given plainly: a mapping from name to arity covering both
actions (``pick_up`` → 1) and state predicates (``cold`` → 1), and the set of
names that are state predicates. Any object with ``arities`` and
``predicates`` attributes of those types can be passed via
:func:`check_against`.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from dataclasses import dataclass
from difflib import get_close_matches
from enum import Enum
from typing import Protocol

from cook2ltl.ltl.ast import Atom, Formula


class AtomKind(Enum):
    ACTION = "action"  # done by the robot; at most one per step
    PREDICATE = "predicate"  # a fact about the world, e.g. cold(apple)


class Primitives(Protocol):
    arities: Mapping[str, int]
    predicates: Collection[str]


@dataclass(frozen=True)
class AtomProblem:
    atom: Atom
    message: str


def atom_kind(atom: Atom, predicates: Collection[str]) -> AtomKind:
    return AtomKind.PREDICATE if atom.name in predicates else AtomKind.ACTION


def split_atoms(formula: Formula, predicates: Collection[str]) -> tuple[frozenset[Atom], frozenset[Atom]]:
    """(actions, state predicates) among the formula's atoms."""
    preds = frozenset(a for a in formula.atoms if a.name in predicates)
    return formula.atoms - preds, preds


def check_atoms(
    formula: Formula, arities: Mapping[str, int], predicates: Collection[str] = ()
) -> tuple[AtomProblem, ...]:
    """Problems with the formula's atoms: unknown names and wrong argument counts.

    Every name, action or predicate, must be in ``arities``; ``predicates``
    only decides whether a message speaks of an action or a predicate.
    """
    problems = []
    for atom in sorted(formula.atoms, key=lambda a: a.key):
        kind = atom_kind(atom, predicates).value
        if atom.name not in arities:
            hint = get_close_matches(atom.name, list(arities), n=1)
            suggestion = f"; did you mean {hint[0]!r}?" if hint else ""
            problems.append(AtomProblem(atom, f"unknown {kind} {atom.name!r}{suggestion}"))
            continue
        want, got = arities[atom.name], len(atom.args)
        if want != got:
            noun = "argument" if want == 1 else "arguments"
            problems.append(
                AtomProblem(atom, f"{kind} {atom.name!r} takes {want} {noun}, got {got} in {atom.text}")
            )
    return tuple(problems)


def check_against(formula: Formula, primitives: Primitives) -> tuple[AtomProblem, ...]:
    """:func:`check_atoms` for a primitive-set object."""
    return check_atoms(formula, primitives.arities, primitives.predicates)
