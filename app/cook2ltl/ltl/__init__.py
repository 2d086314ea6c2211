"""LTLf engine: parse, print, simplify, progress and monitor formulas, build DFAs.

The core is plain functions over immutable, hash-consed formulas; only the
parser needs a library (lark). Semantics are stated in :mod:`.progress`.
"""

from cook2ltl.ltl import automaton as _automaton
from cook2ltl.ltl import order as _order
from cook2ltl.ltl import progress as _progress
from cook2ltl.ltl import simplify as _simplify
from cook2ltl.ltl.ast import (
    FALSE, TRUE, Always, And, Atom, Equiv, Eventually, Formula, Implies, Next, Not, Or, Release, StrongRelease,
    Until, WeakNext, WeakUntil, holds_at_end,
)
from cook2ltl.ltl.limits import FormulaTooLarge
from cook2ltl.ltl.parser import LTLSyntaxError, parse
from cook2ltl.ltl.printer import to_spot, to_unicode
from cook2ltl.ltl.progress import Monitored, Verdict, holds, monitor, progress, verdict
from cook2ltl.ltl.simplify import simplify

__all__ = [
    "clear_caches", "FALSE", "TRUE", "Always", "And", "Atom", "Equiv", "Eventually", "Formula", "FormulaTooLarge",
    "Implies", "LTLSyntaxError", "Next", "Not", "Or", "Release", "Monitored", "StrongRelease", "Until",
    "Verdict", "WeakNext", "WeakUntil", "holds", "holds_at_end", "monitor", "parse", "progress",
    "simplify", "to_spot", "to_unicode", "verdict",
]  # fmt: skip


def clear_caches() -> None:
    """Empty the memo tables of ordering, progression, simplification and the DFA.

    They keep the formulas they saw alive; a long session may drop them, and
    a benchmark must, to time a cold start.
    """
    _order.clear_compared()
    _progress.clear_memo()
    for cached in (
        _simplify.implies,
        _simplify.simplify,
        _automaton.normal_form,
    ):
        cached.cache_clear()
