"""A DFA for an LTLf formula, built by progression.

Each state is a remaining obligation; reading a step progresses it. A state
accepts when the trace may end there (``holds_at_end``). Obligations are kept
in disjunctive normal form over their temporal parts, so only finitely many
arise and the construction always ends.

The alphabet is explicit. For recipes it is :func:`action_alphabet`: one
action per step (or an action the formula does not mention), together with
any combination of the state predicates. :func:`powerset_alphabet` gives the
usual LTLf alphabet, every set of atoms.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable
from dataclasses import dataclass
from functools import lru_cache
from itertools import chain, combinations

from cook2ltl.ltl.ast import FALSE, TRUE, And, Atom, Formula, Not, Or, holds_at_end
from cook2ltl.ltl.limits import FormulaTooLarge
from cook2ltl.ltl.progress import progress
from cook2ltl.ltl.simplify import and_, or_, simplify

Symbol = frozenset[Atom]


# Clauses one normal form may have: a conjunction of n two-way disjunctions
# has 2ⁿ of them, and dropping subsumed clauses compares every pair.
MAX_CLAUSES = 1024


class AutomatonTooLarge(FormulaTooLarge):
    """The DFA would exceed the state budget, or a state its clause budget."""


@dataclass(frozen=True)
class DFA:
    alphabet: tuple[Symbol, ...]
    states: tuple[Formula, ...]  # each state's remaining obligation
    initial: int
    accepting: frozenset[int]
    delta: tuple[tuple[int, ...], ...]  # delta[state][symbol index] -> state

    @property
    def atoms(self) -> frozenset[Atom]:
        return frozenset().union(*self.alphabet)

    def symbol_index(self, step: Iterable[Atom]) -> int:
        """The letter for a trace step; atoms the alphabet does not know are ignored."""
        letter = frozenset(step) & self.atoms
        try:
            return self.alphabet.index(letter)
        except ValueError:
            names = ", ".join(sorted(a.text for a in letter))
            raise ValueError(f"step {{{names}}} is not a letter of this automaton") from None

    def run(self, trace: Iterable[Iterable[Atom]]) -> int:
        """The state reached after the trace."""
        state = self.initial
        for step in trace:
            state = self.delta[state][self.symbol_index(step)]
        return state

    def accepts(self, trace: Iterable[Iterable[Atom]]) -> bool:
        return self.run(trace) in self.accepting


def _atoms_sorted(atoms: Iterable[Atom]) -> list[Atom]:
    return sorted(atoms, key=lambda a: a.key)


def powerset_alphabet(atoms: Collection[Atom]) -> tuple[Symbol, ...]:
    """Every set of the atoms: the standard LTLf alphabet."""
    ordered = _atoms_sorted(atoms)
    subsets = chain.from_iterable(combinations(ordered, k) for k in range(len(ordered) + 1))
    return tuple(frozenset(s) for s in subsets)


def action_alphabet(atoms: Collection[Atom], predicates: Collection[str] = ()) -> tuple[Symbol, ...]:
    """At most one action per step, plus any set of state predicates.

    ``predicates`` names the state predicates (``cold`` for ``cold(apple)``);
    every other atom is an action. The letter without an action stands for
    every action the formula does not mention.
    """
    actions = _atoms_sorted(a for a in atoms if a.name not in predicates)
    states = powerset_alphabet([a for a in atoms if a.name in predicates])
    return tuple(s if a is None else s | {a} for a in [None, *actions] for s in states)


def _dnf(root: Formula) -> frozenset[frozenset[Formula]]:
    """Clauses (sets of conjuncts) whose disjunction is ``root``; no And/Or inside.

    Bottom up over the ∧ and ∨ nodes, with a loop rather than recursion.
    """
    done: dict[Formula, frozenset[frozenset[Formula]]] = {}
    stack = [root]
    while stack:
        f = stack.pop()
        if f in done:
            continue
        pending = [a for a in f.args if a not in done] if isinstance(f, (And, Or)) else []
        if pending:
            stack += [f, *pending]
            continue
        done[f] = _clauses(f, done)
    return done[root]


def _clauses(f: Formula, done: dict[Formula, frozenset[frozenset[Formula]]]) -> frozenset[frozenset[Formula]]:
    """The clauses of ``f``, those of its operands already in ``done``."""
    if f is TRUE:
        return frozenset({frozenset()})
    if f is FALSE:
        return frozenset()
    if isinstance(f, Or):
        clauses = frozenset().union(*(done[a] for a in f.args))
    elif isinstance(f, And):
        clauses = frozenset({frozenset()})
        for a in f.args:
            _check_clauses(len(clauses) * len(done[a]))
            clauses = frozenset(c | d for c in clauses for d in done[a])
    else:
        return frozenset({frozenset({f})})
    _check_clauses(len(clauses))
    return clauses


def _check_clauses(count: int) -> None:
    if count > MAX_CLAUSES:
        raise AutomatonTooLarge(f"a state of the automaton would have more than {MAX_CLAUSES:,} clauses.")


@lru_cache(maxsize=1 << 16)
def normal_form(f: Formula) -> Formula:
    """``f`` as a disjunction of conjunctions without contradictory or subsumed clauses."""
    clauses = [c for c in _dnf(f) if not any(Not(x) in c for x in c if not isinstance(x, Not))]
    minimal = [c for c in clauses if not any(d < c for d in clauses)]
    return or_(*(and_(*c) for c in minimal))


def build_dfa(
    formula: Formula,
    alphabet: tuple[Symbol, ...] | None = None,
    *,
    max_states: int = 10_000,
) -> DFA:
    """The DFA of ``formula``; by default over its :func:`action_alphabet` (no predicates)."""
    if alphabet is None:
        alphabet = action_alphabet(formula.atoms)
    start = normal_form(simplify(formula))
    index = {start: 0}
    states, rows = [start], []
    while len(rows) < len(states):
        current = states[len(rows)]
        row = []
        for letter in alphabet:
            target = normal_form(progress(current, letter))
            if target not in index:
                if len(states) >= max_states:
                    raise AutomatonTooLarge(f"the automaton would have more than {max_states:,} states.")
                index[target] = len(states)
                states.append(target)
            row.append(index[target])
        rows.append(tuple(row))
    accepting = frozenset(i for i, s in enumerate(states) if holds_at_end(s))
    return DFA(tuple(alphabet), tuple(states), 0, accepting, tuple(rows))


def minimise(dfa: DFA) -> DFA:
    """The minimal DFA of the same language (Moore's partition refinement).

    Each merged state keeps the smallest of its obligations as its label.
    """
    block = [int(s in dfa.accepting) for s in range(len(dfa.states))]
    while True:
        # Split blocks whose states disagree on where some letter leads.
        signature = [(block[s], tuple(block[t] for t in dfa.delta[s])) for s in range(len(block))]
        renumber = {sig: i for i, sig in enumerate(dict.fromkeys(signature))}
        if len(renumber) == len(set(block)):
            break
        block = [renumber[sig] for sig in signature]
    # Number the blocks in the order their first state was discovered.
    order = {b: i for i, b in enumerate(dict.fromkeys(block))}
    members: dict[int, list[int]] = {}
    for s, b in enumerate(block):
        members.setdefault(order[b], []).append(s)
    states = tuple(
        min((dfa.states[s] for s in ms), key=lambda f: (f.size, f.key)) for _, ms in sorted(members.items())
    )
    delta = tuple(tuple(order[block[t]] for t in dfa.delta[ms[0]]) for _, ms in sorted(members.items()))
    accepting = frozenset(order[block[s]] for s in dfa.accepting)
    return DFA(dfa.alphabet, states, order[block[dfa.initial]], accepting, delta)


def _reachable(dfa: DFA, starts: Iterable[int]) -> set[int]:
    seen = set(starts)
    todo = list(seen)
    while todo:
        for t in dfa.delta[todo.pop()]:
            if t not in seen:
                seen.add(t)
                todo.append(t)
    return seen


def dead_states(dfa: DFA) -> frozenset[int]:
    """States from which no trace is accepted: the recipe can no longer succeed."""
    live = set(dfa.accepting)
    predecessors: dict[int, set[int]] = {}
    for s, row in enumerate(dfa.delta):
        for t in row:
            predecessors.setdefault(t, set()).add(s)
    todo = list(live)
    while todo:
        for p in predecessors.get(todo.pop(), ()):
            if p not in live:
                live.add(p)
                todo.append(p)
    return frozenset(range(len(dfa.states))) - live


def is_satisfiable(formula: Formula, alphabet: tuple[Symbol, ...] | None = None) -> bool:
    """Is some non-empty finite trace over the alphabet a model of the formula?"""
    dfa = build_dfa(formula, alphabet)
    after_one_step = _reachable(dfa, dfa.delta[dfa.initial])
    return bool(after_one_step & dfa.accepting)
