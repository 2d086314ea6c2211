"""How much the LTL engine takes on, and the error it raises past that.

No operation on formulas recurses with the formula's depth: the parser is an
LALR automaton, the AST orders and prints with loops, progression runs on an
explicit stack, and the one recursive test (does x imply y, in simplify.py)
gives up after PROOF_STEPS pairs. So depth alone never crashes anything. What
is left to bound is work and output, with these limits:

* ``MAX_FORMULA_CHARS`` — formula text given to the parser. Typed formulas are
  a few hundred characters; the limit keeps parsing (and the per-node atom
  sets, which grow with the square of a chain of distinct atoms) well under a
  second.
* ``MAX_WORK`` — units of work one operation (one step of progression, one
  simplification) may do. A unit is a few microseconds: one subformula
  progressed, one pair of subformulas compared, or 32 atoms gathered into a
  new node. A step of a 500-step recipe takes a few hundred units; the limit
  is a second or so, and also bounds how many nodes one step adds.
* ``MAX_PRINTED_NODES`` — nodes of a formula written out as text. Shared
  subformulas are printed every time they occur, so a formula of a few hundred
  distinct nodes can print to gigabytes; past this limit printing is refused.
"""

from __future__ import annotations

import threading

from cook2ltl.errors import UserError

MAX_FORMULA_CHARS = 20_000
MAX_WORK = 200_000
MAX_PRINTED_NODES = 1_000_000

_HINT = "split the formula into smaller ones, or write it with fewer nested operators"


class FormulaTooLarge(UserError, ValueError):
    """A formula past one of the limits above; a ValueError too, like a syntax error."""

    def __init__(self, message: str, hint: str = _HINT) -> None:
        super().__init__(message, hint)


class _Spent(threading.local):
    units = 0


_SPENT = _Spent()  # per thread, so concurrent workers do not charge each other


def charge(units: int = 1) -> None:
    """Count work done in this thread."""
    _SPENT.units += units


class WorkLimit:
    """The work of one operation, in this thread: raises FormulaTooLarge once
    more than MAX_WORK units are spent since it was made."""

    def __init__(self, what: str) -> None:
        self.what = what
        self.start = _SPENT.units

    def spend(self) -> None:
        """Count one unit of the operation's own work, and check the total."""
        _SPENT.units += 1
        if _SPENT.units - self.start > MAX_WORK:
            raise FormulaTooLarge(f"{self.what} needs more than {MAX_WORK:,} steps of work; the formula is too large.")
