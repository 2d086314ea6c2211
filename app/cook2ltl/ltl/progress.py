"""LTLf progression (Bacchus & Kabanza) and a step-by-step monitor.

A trace is a finite sequence of steps; a step is the set of atoms true in it
(the action done and the state predicates that hold). ``progress(f, step)``
is the obligation the *rest* of the trace must meet for the whole trace to
satisfy ``f``. The rest may be empty — a recipe ends — and
:func:`~cook2ltl.ltl.ast.holds_at_end` says whether ending now is fine.

Semantics (finite traces, LTLf), stated once for the whole package:

* Spot ``X`` is the **weak** next (``WeakNext``): true at the last step.
  Spot ``X[!]`` is the **strong** next (``Next``): false at the last step.
  This is Spot's own LTLf reading; flloat and ltlf2dfa write them ``WX`` and
  ``X``, and the oracle tests translate accordingly.
* ``F U M`` are strong (need a step where their goal holds), ``G R W`` weak.
* A trace of n steps satisfies ``f`` iff ``holds_at_end`` of ``f`` progressed
  through its n steps is true, and this is exactly the LTLf semantics for
  n ≥ 1. For n = 0 (no step yet) it reads the formula on the empty trace,
  where nothing happens: atoms false, strong operators false, weak ones
  true, ``¬ ∧ ∨`` as usual.

Progressing a strong next ``X[!]ψ`` yields ``ψ`` — or ``ψ ∧ ◇⊤`` ("and the
trace goes on") when ``ψ`` alone would accept the trace ending there; the weak
next ``Xψ`` yields ``ψ`` or ``ψ ∨ □⊥`` ("or the trace has ended").
"""

from __future__ import annotations

from collections.abc import Generator, Iterable, Iterator
from dataclasses import dataclass
from enum import Enum

from cook2ltl.ltl.ast import (
    FALSE, TRUE, Always, And, Atom, Constant, Equiv, Eventually, Formula, Implies, Next, Not, Or, Release,
    StrongRelease, Until, WeakNext, WeakUntil, holds_at_end, negate,
)
from cook2ltl.ltl.limits import WorkLimit
from cook2ltl.ltl.simplify import EMPTY, NONEMPTY, and_, equiv_, or_

Letter = frozenset[Atom]  # one position of a trace: the atoms true there


class Verdict(Enum):
    """Where a trace stands after its last step."""

    SATISFIED = "satisfied"  # every continuation, the empty one included, satisfies
    VIOLATED = "violated"  # no continuation can satisfy
    PRESUMABLY_TRUE = "presumably_true"  # satisfied if the trace ended now
    PRESUMABLY_FALSE = "presumably_false"  # violated if the trace ended now

    @property
    def holds(self) -> bool:
        """Does the trace so far satisfy the formula (if it ends here)?"""
        return self in (Verdict.SATISFIED, Verdict.PRESUMABLY_TRUE)


def verdict(remaining: Formula) -> Verdict:
    """The verdict for a remaining obligation."""
    if remaining is TRUE:
        return Verdict.SATISFIED
    if remaining is FALSE:
        return Verdict.VIOLATED
    return Verdict.PRESUMABLY_TRUE if holds_at_end(remaining) else Verdict.PRESUMABLY_FALSE


def progress(formula: Formula, step: Iterable[Atom]) -> Formula:
    """The obligation left for the rest of the trace after ``step``.

    Raises :class:`~cook2ltl.ltl.limits.FormulaTooLarge` rather than work
    past :data:`~cook2ltl.ltl.limits.MAX_WORK` on one step.
    """
    # Atoms the formula does not mention cannot matter; dropping them makes
    # the memo table hit far more often.
    step = frozenset(step) & formula.atoms
    answer = _known(formula, step)
    return answer if answer is not None else _progress(formula, step)


# Progressions already worked out, by (subformula, step); like an LRU cache
# it keeps what it holds alive, so past this many entries it starts afresh.
_MEMO: dict[tuple[Formula, Letter], Formula] = {}
_MEMO_ENTRIES = 1 << 18


def clear_memo() -> None:
    _MEMO.clear()


def _progress(root: Formula, step: Letter) -> Formula:
    """Progression on an explicit stack of rules (see :func:`_rule`), so a
    formula of any depth progresses without recursion."""
    limit = WorkLimit("progressing the formula by one step")
    stack = [(root, _rule(root))]
    answer = None
    while True:
        node, rule = stack[-1]
        limit.spend()
        try:
            operand = rule.send(answer)
        except StopIteration as finished:
            answer = finished.value
            if len(_MEMO) >= _MEMO_ENTRIES:
                _MEMO.clear()
            _MEMO[node, step] = answer
            stack.pop()
            if not stack:
                return answer
            continue
        answer = _known(operand, step)
        if answer is None:
            stack.append((operand, _rule(operand)))


def _known(f: Formula, step: Letter) -> Formula | None:
    """The progression when it needs no work: of a constant, an atom or a
    negated atom, or one in the memo table; None otherwise."""
    match f:
        case Constant():
            return f
        case Atom():
            return TRUE if f in step else FALSE
        case Not(arg=Atom() as a):
            return FALSE if a in step else TRUE
    return _MEMO.get((f, step))


def _rule(f: Formula) -> Generator[Formula, Formula, Formula]:
    """The progression of one operator: ``(yield g)`` is the progression of ``g``."""
    match f:
        case Not(arg=inner):
            return (yield negate(inner))
        case And(args=args):
            return (yield from _all_of(args))
        case Or(args=args):
            return (yield from _any_of(args))
        case Implies(left=a, right=b):
            return (yield from _any_of((Not(a), b)))
        case Equiv(left=a, right=b):
            # The sides progressed, still an equivalence: the expansion
            # (a ∧ b) ∨ (¬a ∧ ¬b) would double the formula at each nested ↔.
            return equiv_((yield a), (yield b))
        case Next(arg=a):
            return and_(a, NONEMPTY) if holds_at_end(a) else a
        case WeakNext(arg=a):
            return a if holds_at_end(a) else or_(a, EMPTY)
        case Eventually(arg=Eventually() as inner) | Always(arg=Always() as inner):
            return (yield inner)  # ◇◇φ is ◇φ, □□φ is □φ: a long run progresses as one
        case Eventually(arg=a):
            return or_((yield a), f)
        case Always(arg=a):
            return and_((yield a), f)
        case Until(left=a, right=b) | WeakUntil(left=a, right=b):
            # b now, or a now and the same obligation from the next step on.
            now = yield b
            return now if now is TRUE else or_(now, and_((yield a), f))
        case Release(left=a, right=b) | StrongRelease(left=a, right=b):
            # b now, and either a now (released) or the same obligation next.
            now = yield b
            return now if now is FALSE else and_(now, or_((yield a), f))
    raise TypeError(f"not a formula: {f!r}")


def _all_of(operands: tuple[Formula, ...]) -> Generator[Formula, Formula, Formula]:
    # Operands are sorted atoms first, so a sequence like a ∧ ◇(…) stops at a
    # failed atom without walking the rest of the recipe.
    return (yield from _each(operands, FALSE, and_))


def _any_of(operands: tuple[Formula, ...]) -> Generator[Formula, Formula, Formula]:
    return (yield from _each(operands, TRUE, or_))


def _each(operands: tuple[Formula, ...], absorbing: Formula, combine) -> Generator[Formula, Formula, Formula]:
    """Each operand progressed in turn (sent back by the caller), stopping at the first that is ``absorbing``."""
    done = []
    for a in operands:
        p = yield a
        if p is absorbing:
            return absorbing
        done.append(p)
    return combine(*done)


def progress_trace(formula: Formula, trace: Iterable[Iterable[Atom]]) -> Formula:
    """The obligation left after the whole trace."""
    for step in trace:
        formula = progress(formula, step)
    return formula


def holds(formula: Formula, trace: Iterable[Iterable[Atom]]) -> bool:
    """Does the finite trace satisfy the formula (LTLf)?"""
    return holds_at_end(progress_trace(formula, trace))


@dataclass(frozen=True)
class Monitored:
    index: int  # 1 for the first step
    step: Letter
    remaining: Formula
    verdict: Verdict


def monitor(formula: Formula, trace: Iterable[Iterable[Atom]]) -> Iterator[Monitored]:
    """Progress through the trace, yielding the obligation and verdict after each step.

    Once the obligation is ``⊤`` or ``⊥`` it never changes; the monitor still
    reports every step so the caller can show them all.
    """
    for index, step in enumerate(trace, start=1):
        step = frozenset(step)
        formula = progress(formula, step)
        yield Monitored(index, step, formula, verdict(formula))
