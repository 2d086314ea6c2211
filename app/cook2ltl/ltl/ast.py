"""Immutable, hash-consed LTLf formulas in a canonical form.

Every node is interned: building the same formula twice returns the same
object, so equality is identity and hashing is cheap. That is what makes the
memo tables of progression and the DFA construction fast.

Canonical form, applied by the constructors themselves:

* ``And``/``Or`` are n-ary, flattened, deduplicated and sorted; ``TRUE`` and
  ``FALSE`` are folded away, and a single operand is returned as is.
* ``Not(Not(f))`` is ``f``; ``Not`` of a constant is the other constant.

Next operators: ``Next`` is the *strong* next (Spot ``X[!]``: a next step must
exist) and ``WeakNext`` the *weak* one (Spot ``X`` under Spot's LTLf reading:
true at the last step). The other operators are as in Spot: ``M`` is the
strong release, ``W`` the weak until.
"""

from __future__ import annotations

import weakref
from bisect import insort
from collections.abc import Iterator
from dataclasses import dataclass, fields
from typing import ClassVar

from cook2ltl.ltl.limits import charge
from cook2ltl.ltl.order import SORT_KEY

_INTERNED: weakref.WeakValueDictionary = weakref.WeakValueDictionary()
_FORBIDDEN_IN_NAMES = frozenset('()",')


class Formula:
    """Base class of all formula nodes (never instantiated itself)."""

    rank: ClassVar[int]  # place in the canonical order (see order.py): constants 0, atoms 1, then operators
    # Set once by ``_intern``, from the children's (so never by recursion):
    atoms: frozenset  # the atoms in the formula
    size: int  # number of nodes
    end_ok: bool  # see holds_at_end()
    promised: frozenset | None  # atoms every model makes true at some step; None: no model

    @property
    def key(self):
        """Sort key of the canonical order (see :mod:`cook2ltl.ltl.order`)."""
        return SORT_KEY(self)

    def __reduce__(self):
        # Pickling must go back through the constructor to stay interned.
        return (_rebuild, (type(self), self.constructor_args()))

    def constructor_args(self) -> tuple:
        raise NotImplementedError

    @property
    def children(self) -> tuple[Formula, ...]:
        return tuple(c for c in self.constructor_args() if isinstance(c, Formula))


def _rebuild(cls, args):
    return cls(*args)


def _intern(cls, values: tuple, children: tuple) -> Formula:
    lookup = (cls, values)
    node = _INTERNED.get(lookup)
    if node is not None:
        return node
    node = object.__new__(cls)
    for field, value in zip(fields(cls), values, strict=True):
        object.__setattr__(node, field.name, value)
    atoms = frozenset().union(*(c.atoms for c in children)) if children else frozenset()
    # Gathering the children's atoms (and promises, below) is the cost of a new
    # node that grows with the formula: about a unit of work per 32 atoms.
    charge(1 + sum(len(c.atoms) for c in children) // 32)
    object.__setattr__(node, "atoms", atoms)
    object.__setattr__(node, "size", 1 + sum(c.size for c in children))
    end_ok, promised = _facts(node)
    object.__setattr__(node, "end_ok", end_ok)
    object.__setattr__(node, "promised", promised)
    _INTERNED[lookup] = node
    return node


def _facts(f: Formula) -> tuple[bool, frozenset | None]:
    """(holds_at_end(f), promised atoms), from the children's.

    Classes are matched by name at call time, so this may come before them.
    """
    match f:
        case Constant(value=v):
            return v, (frozenset() if v else None)
        case Atom():
            return False, frozenset((f,))
        case Not(arg=a):
            return not a.end_ok, frozenset()
        case And(args=args):
            promised = [a.promised for a in args]
            union = None if None in promised else frozenset().union(*promised)
            return all(a.end_ok for a in args), union
        case Or(args=args):
            promised = [a.promised for a in args if a.promised is not None]
            common = frozenset.intersection(*promised) if promised else None
            return any(a.end_ok for a in args), common
        case Next(arg=a) | Eventually(arg=a) | Until(right=a):
            return False, a.promised
        case StrongRelease(left=a, right=b):
            return False, (None if None in (a.promised, b.promised) else a.promised | b.promised)
        case WeakNext() | Always() | Release() | WeakUntil():
            return True, frozenset()
        case Implies(left=a, right=b):
            return (not a.end_ok) or b.end_ok, frozenset()
        case Equiv(left=a, right=b):
            return a.end_ok == b.end_ok, frozenset()
    raise TypeError(f"not a formula: {f!r}")


@dataclass(frozen=True, eq=False, init=False, repr=False)
class Constant(Formula):
    value: bool
    rank: ClassVar[int] = 0

    def __new__(cls, value: bool):
        return _intern(cls, (bool(value),), ())

    def constructor_args(self) -> tuple:
        return (self.value,)


TRUE = Constant(True)
FALSE = Constant(False)


@dataclass(frozen=True, eq=False, init=False, repr=False)
class Atom(Formula):
    """An atomic proposition, e.g. ``pick_up(knife)`` = ``Atom("pick_up", ("knife",))``."""

    name: str
    args: tuple[str, ...]
    rank: ClassVar[int] = 1

    def __new__(cls, name: str, args: tuple[str, ...] | list[str] = ()):
        args = tuple(args)
        for part in (name, *args):
            if not isinstance(part, str) or not part or part != part.strip():
                raise ValueError(f"bad atom part {part!r}: empty or padded with spaces")
            if _FORBIDDEN_IN_NAMES & set(part):
                raise ValueError(f'bad atom part {part!r}: contains one of ( ) " ,')
        node = _intern(cls, (name, args), ())
        if not node.atoms:
            object.__setattr__(node, "atoms", frozenset((node,)))
        return node

    def constructor_args(self) -> tuple:
        return (self.name, self.args)

    @property
    def text(self) -> str:
        """The atom as written in a trace step, e.g. ``slice(tomato, knife)``."""
        return f"{self.name}({', '.join(self.args)})" if self.args else self.name


@dataclass(frozen=True, eq=False, init=False, repr=False)
class _Unary(Formula):
    arg: Formula

    def __new__(cls, arg: Formula):
        return _intern(cls, (arg,), (arg,))

    def constructor_args(self) -> tuple:
        return (self.arg,)


@dataclass(frozen=True, eq=False, init=False, repr=False)
class _Binary(Formula):
    left: Formula
    right: Formula

    def __new__(cls, left: Formula, right: Formula):
        return _intern(cls, (left, right), (left, right))

    def constructor_args(self) -> tuple:
        return (self.left, self.right)


class Not(_Unary):
    rank = 2

    def __new__(cls, arg: Formula):
        if isinstance(arg, Not):
            return arg.arg
        if isinstance(arg, Constant):
            return FALSE if arg.value else TRUE
        return super().__new__(cls, arg)


class Next(_Unary):
    """Strong next, Spot ``X[!]``: there is a next step and ``arg`` holds there."""

    rank = 3


class WeakNext(_Unary):
    """Weak next, Spot ``X`` (LTLf reading): if there is a next step, ``arg`` holds there."""

    rank = 4


class Eventually(_Unary):
    rank = 5


class Always(_Unary):
    rank = 6


class Until(_Binary):
    rank = 7


class Release(_Binary):
    rank = 8


class WeakUntil(_Binary):
    rank = 9


class StrongRelease(_Binary):
    """Spot ``M``: ``a M b`` = ``b U (a & b)``."""

    rank = 10


@dataclass(frozen=True, eq=False, init=False, repr=False)
class _NAry(Formula):
    args: tuple[Formula, ...]
    unit: ClassVar[Constant]
    zero: ClassVar[Constant]

    def __new__(cls, *operands: Formula):
        runs: list[tuple[Formula, ...]] = []  # the sorted operands of nested nodes of this class
        loose: set[Formula] = set()
        for op in operands:
            if op is cls.zero:
                return cls.zero
            if isinstance(op, cls):
                runs.append(op.args)
            elif op is not cls.unit:
                loose.add(op)
        # Adding a few operands to a long sorted run (as `a & b & c …` is read)
        # inserts them, instead of sorting the whole run again.
        base: tuple[Formula, ...] = ()
        rest = loose
        if runs:
            base = max(runs, key=len)
            rest = loose.union(*(r for r in runs if r is not base)).difference(base)
        if len(rest) > len(base):
            ordered = sorted(rest.union(base), key=SORT_KEY)
        else:
            ordered = list(base)
            for f in rest:
                insort(ordered, f, key=SORT_KEY)
        if not ordered:
            return cls.unit
        if len(ordered) == 1:
            return ordered[0]
        return _intern(cls, (tuple(ordered),), tuple(ordered))

    def constructor_args(self) -> tuple:
        return self.args


class And(_NAry):
    rank = 11
    unit = TRUE
    zero = FALSE


class Or(_NAry):
    rank = 12
    unit = FALSE
    zero = TRUE


class Implies(_Binary):
    rank = 13


class Equiv(_Binary):
    rank = 14


def negate(f: Formula) -> Formula:
    """``¬f`` with the negation pushed one level down (negation normal form, lazily).

    Atoms keep a plain ``Not``; everything else uses its dual, e.g.
    ``¬(a U b) = ¬a R ¬b`` and ``¬X[!]a = X¬a``.
    """
    match f:
        case Constant() | Atom():
            return Not(f)
        case Not(arg=inner):
            return inner
        case And(args=args):
            return Or(*(Not(a) for a in args))
        case Or(args=args):
            return And(*(Not(a) for a in args))
        case Implies(left=a, right=b):
            return And(a, Not(b))
        case Equiv(left=a, right=b):
            return Equiv(a, Not(b))  # not the expansion, which doubles the formula at each nested ↔
        case Next(arg=a):
            return WeakNext(Not(a))
        case WeakNext(arg=a):
            return Next(Not(a))
        case Eventually(arg=a):
            return Always(Not(a))
        case Always(arg=a):
            return Eventually(Not(a))
        case Until(left=a, right=b):
            return Release(Not(a), Not(b))
        case Release(left=a, right=b):
            return Until(Not(a), Not(b))
        case WeakUntil(left=a, right=b):
            return StrongRelease(Not(a), Not(b))
        case StrongRelease(left=a, right=b):
            return WeakUntil(Not(a), Not(b))
    raise TypeError(f"not a formula: {f!r}")


def holds_at_end(f: Formula) -> bool:
    """Does ``f`` hold on the empty rest of a trace, i.e. if the trace ended here?

    A remaining obligation is read over the rest of the trace, which may be
    empty. There nothing happens: atoms are false, the strong operators
    ``X[!] F U M`` are false, the weak ones ``X G R W`` true, and the Boolean
    connectives are the usual ones.
    """
    return f.end_ok


def postorder(root: Formula) -> Iterator[Formula]:
    """Each distinct subformula once, children first; a loop, since a long
    recipe nests deeper than Python's recursion limit."""
    done: set[Formula] = set()
    stack = [root]
    while stack:
        node = stack[-1]
        if node in done:
            stack.pop()
            continue
        pending = [c for c in node.children if c not in done]
        if pending:
            stack.extend(pending)
        else:
            stack.pop()
            done.add(node)
            yield node
