"""Simplify formulas and keep what is left readable.

The rules never restructure a formula into a normal form; they only fold
constants, drop operands that another operand already settles and merge
repeated operators. So after ``pick_up(knife)`` the obligation
``◇(pick_up(knife) ∧ ◇slice(tomato))`` becomes ``◇slice(tomato)``, not a
rewritten equivalent.

Every rule is sound on *possibly empty* traces, because remaining obligations
are read over the rest of a trace, which is empty once the trace ends (see
:func:`cook2ltl.ltl.ast.holds_at_end`). That rules out identities that only
hold on non-empty traces: ``◇⊤`` is not ``⊤`` (it says "the trace goes
on"), nor is ``□⊥`` the same as ``⊥`` (it says "the trace has ended").
"""

from __future__ import annotations

from functools import lru_cache

from cook2ltl.ltl.ast import (
    FALSE, TRUE, Always, And, Atom, Constant, Equiv, Eventually, Formula, Implies, Next, Not, Or, Release,
    StrongRelease, Until, WeakNext, WeakUntil, holds_at_end, postorder,
)
from cook2ltl.ltl.limits import WorkLimit, charge

NONEMPTY = Eventually(TRUE)  # "the trace goes on": false only on the empty rest
EMPTY = Always(FALSE)  # "the trace has ended": true only on the empty rest


# One implication test looks at no more than this many pairs of subformulas
# and past that answers "not proved", which is sound: the proofs the rules
# find in recipes take a few dozen, and the bound also keeps the recursion
# well inside Python's limit.
PROOF_STEPS = 100
# Operands of one ∧ or ∨ compared pairwise for subsumption (the cost grows with
# the square); a longer one only keeps operands a comparison would have dropped.
SUBSUMPTION_OPERANDS = 32


@lru_cache(maxsize=1 << 18)
def implies(x: Formula, y: Formula) -> bool:
    """A cheap, sound and incomplete test of ``x ⇒ y`` on possibly empty traces."""
    return _Proof().implies(x, y)


class _Proof:
    """One implication test: the pairs it has settled and the steps it has left."""

    def __init__(self) -> None:
        self.settled: dict[tuple[Formula, Formula], bool] = {}
        self.steps_left = PROOF_STEPS

    def implies(self, x: Formula, y: Formula) -> bool:
        if x is y or x is FALSE or y is TRUE:
            return True
        answer = self.settled.get((x, y))
        if answer is None:
            if not self.steps_left:
                return False
            self.steps_left -= 1
            charge()
            answer = self.settled[x, y] = self._by_rules(x, y)
        return answer

    def _by_rules(self, x: Formula, y: Formula) -> bool:
        # No rule below proves x ⇒ y unless x promises every atom y promises;
        # checking that first spares a walk down a long recipe.
        px, py = x.promised, y.promised
        if py is None or (px is not None and not py <= px):
            return False
        if isinstance(y, And):
            return all(self.implies(x, c) for c in y.args)
        if isinstance(x, Or):
            return all(self.implies(c, y) for c in x.args)
        if isinstance(x, And) and any(self.implies(c, y) for c in x.args):
            return True
        if isinstance(y, Or) and any(self.implies(x, c) for c in y.args):
            return True
        if isinstance(y, Eventually):
            # x needs a step and entails the goal now, or x promises it later.
            if not holds_at_end(x) and self.implies(x, y.arg):
                return True
            if isinstance(x, Eventually) and self.implies(x.arg, y):
                return True
            if isinstance(x, (Until, StrongRelease)) and self.implies(x.right, y):
                return True
        if isinstance(x, Always) and holds_at_end(y) and self.implies(x.arg, y):
            return True
        # All temporal operators are monotone in each operand.
        if (type(x), type(y)) not in _WEAKENINGS:
            return False
        return all(self.implies(a, b) for a, b in zip(x.children, y.children, strict=True))


# Operator pairs (stronger, weaker) whose operands may then be compared pairwise.
_WEAKENINGS = {
    (Next, Next), (WeakNext, WeakNext), (Next, WeakNext),
    (Eventually, Eventually), (Always, Always),
    (Until, Until), (Release, Release), (WeakUntil, WeakUntil), (StrongRelease, StrongRelease),
    (Until, WeakUntil), (StrongRelease, Release),
}  # fmt: skip


def and_(*operands: Formula) -> Formula:
    """Conjunction without contradictions and without operands a stronger one settles."""
    return _without_settled(And(*operands), And, FALSE, implies)


def or_(*operands: Formula) -> Formula:
    """Disjunction without operands that a weaker one already covers; ``x ∨ ¬x`` is ``⊤``."""
    return _without_settled(Or(*operands), Or, TRUE, lambda weaker, stronger: implies(stronger, weaker))


def _without_settled(f: Formula, op: type, absorbing: Formula, settles) -> Formula:
    """``f`` (built by ``op``, ∧ or ∨) as ``absorbing`` when it holds an operand and its negation, else without
    the operands another one settles: ``settles(k, a)`` says that ``k`` makes ``a`` redundant."""
    if not isinstance(f, op):
        return f
    present = set(f.args)
    if any(isinstance(a, Not) and a.arg in present for a in f.args):
        return absorbing
    if len(f.args) > SUBSUMPTION_OPERANDS:
        return f
    kept: list[Formula] = []
    for a in f.args:
        if any(settles(k, a) for k in kept):
            continue
        kept = [k for k in kept if not settles(a, k)]
        kept.append(a)
    return op(*kept)


def equiv_(a: Formula, b: Formula) -> Formula:
    """``a ↔ b`` with constants folded; ``x ↔ x`` is ``⊤`` and ``x ↔ ¬x`` is ``⊥``."""
    if a is b:
        return TRUE
    if (isinstance(a, Not) and a.arg is b) or (isinstance(b, Not) and b.arg is a):
        return FALSE
    for x, y in ((a, b), (b, a)):
        if isinstance(x, Constant):
            return y if x.value else Not(y)
    return Equiv(a, b)


def eventually(f: Formula) -> Formula:
    if f is FALSE or isinstance(f, Eventually):
        return f
    return Eventually(f)


def always(f: Formula) -> Formula:
    if f is TRUE or isinstance(f, Always):
        return f
    return Always(f)


def _and_nonempty(f: Formula) -> Formula:
    """``f`` on a trace that goes on: the constant rules below need it."""
    return and_(f, NONEMPTY) if holds_at_end(f) else f


def _or_empty(f: Formula) -> Formula:
    return f if holds_at_end(f) else or_(f, EMPTY)


@lru_cache(maxsize=1 << 16)
def simplify(f: Formula) -> Formula:
    """Fold constants, drop settled operands and merge ``◇◇``, ``□□``, bottom up."""
    limit = WorkLimit("simplifying the formula")
    done: dict[Formula, Formula] = {}
    for g in postorder(f):
        limit.spend()
        done[g] = _simplify_node(g, [done[c] for c in g.children])
    return done[f]


def _simplify_node(f: Formula, kids: list[Formula]) -> Formula:
    """One node, its children already simplified into ``kids``."""
    match f:
        case Constant() | Atom():
            return f
        case Not():
            return Not(kids[0])
        case And():
            return and_(*kids)
        case Or():
            return or_(*kids)
        case Next():
            return FALSE if kids[0] is FALSE else Next(kids[0])
        case WeakNext():
            return TRUE if kids[0] is TRUE else WeakNext(kids[0])
        case Eventually():
            return eventually(kids[0])
        case Always():
            return always(kids[0])
        case Implies():
            return _implies(*kids)
        case Equiv():
            return equiv_(*kids)
    return _binary_temporal(type(f), *kids)


def _implies(a: Formula, b: Formula) -> Formula:
    if a is TRUE:
        return b
    if a is FALSE or b is TRUE:
        return TRUE
    if b is FALSE:
        return Not(a)
    return Implies(a, b)


def _binary_temporal(op: type, a: Formula, b: Formula) -> Formula:
    """Constant operands of U R W M; each case is the operator's definition."""
    if op is Until:
        if b is FALSE or b is TRUE:
            return NONEMPTY if b is TRUE else FALSE
        if a is TRUE:
            return eventually(b)
        if a is FALSE:
            return _and_nonempty(b)
    elif op is Release:
        if b is TRUE or b is FALSE:
            return TRUE if b is TRUE else EMPTY
        if a is FALSE:
            return always(b)
        if a is TRUE:
            return _or_empty(b)
    elif op is WeakUntil:
        if a is TRUE or b is TRUE:
            return TRUE
        if b is FALSE:
            return always(a)
        if a is FALSE:
            return _or_empty(b)
    else:  # StrongRelease: a M b = b U (a ∧ b)
        if a is FALSE or b is FALSE:
            return FALSE
        if b is TRUE:
            return eventually(a)
        if a is TRUE:
            return _and_nonempty(b)
    return op(a, b)
