"""Shared helpers for the LTL tests: random formulas and traces, and adapters
that hand our formulas to the independent LTLf oracles (flloat, ltlf2dfa+MONA).

The oracles write strong next as ``X`` and weak next as ``WX``; ours follow
Spot's LTLf reading (``X[!]`` strong, ``X`` weak), so ``Next`` maps to ``X``
and ``WeakNext`` to ``WX``. They reject atom names such as ``last``, ``end``,
``true``, so every atom is renamed ``p0``, ``p1``, ….
"""

from __future__ import annotations

import random
import re
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

from hypothesis import strategies as st

from cook2ltl.ltl.ast import (
    FALSE,
    TRUE,
    Always,
    And,
    Atom,
    Constant,
    Equiv,
    Eventually,
    Formula,
    Implies,
    Next,
    Not,
    Or,
    Release,
    StrongRelease,
    Until,
    WeakNext,
    WeakUntil,
)

UNARY = (Not, Next, WeakNext, Eventually, Always)
BINARY = (And, Or, Implies, Equiv, Until, Release, WeakUntil, StrongRelease)


# --- random formulas and traces (seeded, for the oracle comparison) ---------


def random_formula(rng: random.Random, atoms: list[Atom], size: int) -> Formula:
    """A random formula with about ``size`` operators over ``atoms``."""
    if size <= 0:
        roll = rng.random()
        if roll < 0.06:
            return TRUE
        if roll < 0.12:
            return FALSE
        return rng.choice(atoms)
    if rng.random() < 0.4:
        return rng.choice(UNARY)(random_formula(rng, atoms, size - 1))
    left = rng.randint(0, size - 1)
    op = rng.choice(BINARY)
    return op(random_formula(rng, atoms, left), random_formula(rng, atoms, size - 1 - left))


def random_trace(rng: random.Random, atoms: list[Atom], length: int) -> list[frozenset[Atom]]:
    return [frozenset(a for a in atoms if rng.random() < 0.5) for _ in range(length)]


# --- a direct, positional LTLf evaluator (independent of progression) ------


def sat(f: Formula, trace, i: int = 0) -> bool:
    """Textbook LTLf semantics at position ``i`` of a non-empty trace."""
    n = len(trace)
    match f:
        case Constant(value=v):
            return v
        case Atom():
            return f in trace[i]
        case Not(arg=a):
            return not sat(a, trace, i)
        case And(args=args):
            return all(sat(a, trace, i) for a in args)
        case Or(args=args):
            return any(sat(a, trace, i) for a in args)
        case Implies(left=a, right=b):
            return not sat(a, trace, i) or sat(b, trace, i)
        case Equiv(left=a, right=b):
            return sat(a, trace, i) == sat(b, trace, i)
        case Next(arg=a):
            return i + 1 < n and sat(a, trace, i + 1)
        case WeakNext(arg=a):
            return i + 1 >= n or sat(a, trace, i + 1)
        case Eventually(arg=a):
            return any(sat(a, trace, j) for j in range(i, n))
        case Always(arg=a):
            return all(sat(a, trace, j) for j in range(i, n))
        case Until(left=a, right=b):
            return _until(a, b, trace, i)
        case WeakUntil(left=a, right=b):
            return _until(a, b, trace, i) or all(sat(a, trace, j) for j in range(i, n))
        case Release(left=a, right=b):
            return all(sat(b, trace, j) or any(sat(a, trace, k) for k in range(i, j)) for j in range(i, n))
        case StrongRelease(left=a, right=b):
            return _until(b, And(a, b), trace, i)
    raise TypeError(f)


def _until(a, b, trace, i):
    return any(sat(b, trace, j) and all(sat(a, trace, k) for k in range(i, j)) for j in range(i, len(trace)))


# --- hypothesis strategies (for round trips and properties) ----------------

_names = st.from_regex(r"[a-z_][A-Za-z0-9_]{0,6}", fullmatch=True)
_odd_names = st.sampled_from(["true", "false", "Add salt", "last", "end", "x-ray", "Ω"])
_args = st.lists(
    st.one_of(
        st.from_regex(r"[A-Za-z0-9_][A-Za-z0-9_.\-]{0,5}", fullmatch=True),
        st.sampled_from(["chef knife", "350 F", "é"]),
    ),
    max_size=3,
)
atoms_strategy = st.builds(lambda n, a: Atom(n, tuple(a)), st.one_of(_names, _odd_names), _args)


def formulas_strategy(atoms=atoms_strategy, max_leaves: int = 12):
    leaves = st.one_of(st.just(TRUE), st.just(FALSE), atoms)

    def extend(children):
        return st.one_of(
            st.builds(lambda op, f: op(f), st.sampled_from(UNARY), children),
            st.builds(lambda op, a, b: op(a, b), st.sampled_from(BINARY), children, children),
        )

    return st.recursive(leaves, extend, max_leaves=max_leaves)


def small_atoms(n: int = 3) -> list[Atom]:
    return [Atom(f"p{i}") for i in range(n)]


def traces_strategy(atoms: list[Atom], max_len: int = 6):
    step = st.frozensets(st.sampled_from(atoms))
    return st.lists(step, max_size=max_len)


# --- oracle syntax ------------------------------------------------------------


def to_oracle_syntax(f: Formula, names: dict[Atom, str]) -> str:
    """Fully parenthesised LTLf in the syntax flloat and ltlf2dfa share."""

    def go(g: Formula) -> str:
        match g:
            case Constant(value=v):
                return "true" if v else "false"
            case Atom():
                return names.setdefault(g, f"p{len(names)}")
            case Not(arg=a):
                return f"!({go(a)})"
            case Next(arg=a):
                return f"X({go(a)})"
            case WeakNext(arg=a):
                return f"WX({go(a)})"
            case Eventually(arg=a):
                return f"F({go(a)})"
            case Always(arg=a):
                return f"G({go(a)})"
            case And(args=args):
                return "(" + " & ".join(go(a) for a in args) + ")"
            case Or(args=args):
                return "(" + " | ".join(go(a) for a in args) + ")"
            case Implies(left=a, right=b):
                return f"({go(a)} -> {go(b)})"
            case Equiv(left=a, right=b):
                return f"({go(a)} <-> {go(b)})"
            case Until(left=a, right=b):
                return f"({go(a)} U {go(b)})"
            case Release(left=a, right=b):
                return f"({go(a)} R {go(b)})"
            case WeakUntil(left=a, right=b):  # a W b = a U b | G a
                return f"(({go(a)} U {go(b)}) | G({go(a)}))"
            case StrongRelease(left=a, right=b):  # a M b = b U (a & b)
                return f"({go(b)} U ({go(a)} & {go(b)}))"
        raise TypeError(g)

    return go(f)


def oracle_names(atoms: list[Atom]) -> dict[Atom, str]:
    return {a: f"p{i}" for i, a in enumerate(atoms)}


# --- flloat -------------------------------------------------------------------


class FlloatOracle:
    def __init__(self):
        from flloat.parser.ltlf import LTLfParser

        self._parse = LTLfParser()

    def prefix_truths(self, text: str, trace, names: dict[Atom, str]) -> list[bool]:
        """Truth of the formula on every non-empty prefix of the trace."""
        formula = self._parse(text)
        steps = [{names[a]: (a in step) for a in names} for step in trace]
        return [formula.truth(steps[:k], 0) for k in range(1, len(steps) + 1)]


# --- ltlf2dfa + MONA ----------------------------------------------------------


@dataclass(frozen=True)
class MonaDFA:
    variables: tuple[str, ...]  # MONA's free variables, upper-case atom names
    accepting: frozenset[int]
    edges: dict[int, list[tuple[str, int]]]  # state -> [(ternary guard, target)]

    def successor(self, state: int, true_names: set[str]) -> int:
        bits = ["1" if v.lower() in true_names else "0" for v in self.variables]
        for guard, target in self.edges[state]:
            if all(g in ("X", b) for g, b in zip(guard, bits, strict=True)):
                return target
        raise AssertionError(f"MONA DFA has no edge from {state} on {bits}")

    def prefix_acceptance(self, trace, names: dict[Atom, str]) -> list[tuple[bool, int]]:
        """(accepted, state) after each step."""
        # MONA's initial state 0 reads one dummy letter before the trace.
        state, out = self.edges[0][0][1], []
        for step in trace:
            state = self.successor(state, {names[a] for a in step})
            out.append((state in self.accepting, state))
        return out

    def reaches(self, start: int) -> set[int]:
        seen, todo = {start}, [start]
        while todo:
            for _, t in self.edges[todo.pop()]:
                if t not in seen:
                    seen.add(t)
                    todo.append(t)
        return seen


class MonaOracle:
    """ltlf2dfa translates the formula to MONA's logic; MONA builds the DFA.

    We run MONA ourselves on a private file: ltlf2dfa's own ``to_dfa`` writes
    one shared file inside its package and simplifies guards with sympy.
    """

    def __init__(self):
        from ltlf2dfa.base import MonaProgram
        from ltlf2dfa.parser.ltlf import LTLfParser

        self._parse = LTLfParser()
        self._program = MonaProgram

    def dfa(self, text: str) -> MonaDFA:
        program = self._program(self._parse(text)).mona_program()
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp, "f.mona")
            path.write_text(program)
            out = subprocess.run(
                ["mona", "-q", "-u", "-w", str(path)],
                capture_output=True,
                text=True,
                timeout=60,
                check=True,
            ).stdout
        return _parse_mona(out)


def _parse_mona(out: str) -> MonaDFA:
    variables = re.search(r"free variables:([^\n]*)", out).group(1).split()
    accepting = re.search(r"Accepting states:([^\n]*)", out).group(1).split()
    edges: dict[int, list[tuple[str, int]]] = {}
    for src, guard, dst in re.findall(r"State (\d+): ?([01X]*) -> state (\d+)", out):
        edges.setdefault(int(src), []).append((guard, int(dst)))
    return MonaDFA(tuple(variables), frozenset(int(s) for s in accepting), edges)
