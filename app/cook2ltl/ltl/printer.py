"""Print formulas in Unicode (for people) or in Spot's ASCII syntax (for tools).

Both outputs parse back to the same formula: ``parse(to_unicode(f)) is f`` and
``parse(to_spot(f)) is f``. Spot cannot read ``pick_up(knife)``, so the ASCII
printer quotes every atom with arguments: ``"pick_up(knife)"``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from cook2ltl.ltl.ast import (
    Always, And, Atom, Constant, Equiv, Eventually, Formula, Implies, Next, Not, Or, Release, StrongRelease, Until,
    WeakNext, WeakUntil,
)
from cook2ltl.ltl.limits import MAX_PRINTED_NODES, FormulaTooLarge

_NAME = re.compile(r"[a-z_][A-Za-z0-9_]*\Z")
_ARG = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.\-]*\Z")
_KEYWORDS = frozenset({"true", "false"})


@dataclass(frozen=True)
class _Style:
    true: str
    false: str
    prefix: dict[type, str]
    infix: dict[type, str]
    quote_all_args: bool


_UNICODE = _Style(
    true="⊤",
    false="⊥",
    prefix={Not: "¬", Next: "○[!]", WeakNext: "○", Eventually: "◇", Always: "□"},
    infix={
        And: " ∧ ", Or: " ∨ ", Implies: " → ", Equiv: " ↔ ",
        Until: " 𝒰 ", Release: " ℛ ", WeakUntil: " 𝒲 ", StrongRelease: " ℳ ",
    },
    quote_all_args=False,
)  # fmt: skip

_SPOT = _Style(
    true="true",
    false="false",
    prefix={Not: "!", Next: "X[!]", WeakNext: "X", Eventually: "F", Always: "G"},
    infix={
        And: " & ", Or: " | ", Implies: " -> ", Equiv: " <-> ",
        Until: " U ", Release: " R ", WeakUntil: " W ", StrongRelease: " M ",
    },
    quote_all_args=True,
)  # fmt: skip


def to_unicode(f: Formula) -> str:
    """``◇(pick_up(knife) ∧ ◇slice(tomato, knife))``."""
    return _print(f, _UNICODE)


def to_spot(f: Formula) -> str:
    """``F("pick_up(knife)" & F"slice(tomato, knife)")``, readable by Spot."""
    return _print(f, _SPOT)


def atom_to_text(atom: Atom, *, quote_args: bool = False) -> str:
    """The atom as it is written inside a formula, quoted when it must be."""
    plain = (
        _NAME.match(atom.name)
        and atom.name not in _KEYWORDS
        and not (quote_args and atom.args)
        and all(_ARG.match(a) for a in atom.args)
    )
    return atom.text if plain else f'"{atom.text}"'


def _is_atomic(f: Formula) -> bool:
    return isinstance(f, (Atom, Constant))


def _print(root: Formula, style: _Style) -> str:
    """The text of ``root``, written left to right from a stack of pieces
    still to write (text, or a formula to expand), so depth costs no
    recursion and each piece is written once."""
    if root.size > MAX_PRINTED_NODES:
        raise FormulaTooLarge(
            f"the formula has {root.size:,} nodes written out, more than the {MAX_PRINTED_NODES:,} that are printed.",
            "progress it further or print a smaller part; shared parts are written out each time they occur",
        )
    out: list[str] = []
    todo: list[str | Formula] = [root]
    while todo:
        piece = todo.pop()
        if isinstance(piece, str):
            out.append(piece)
        else:
            todo.extend(reversed(_pieces(piece, style)))
    return "".join(out)


def _pieces(f: Formula, style: _Style) -> list[str | Formula]:
    """One node as text around its operands."""
    match f:
        case Constant(value=v):
            return [style.true if v else style.false]
        case Atom():
            return [atom_to_text(f, quote_args=style.quote_all_args)]
        case Not() | Next() | WeakNext() | Eventually() | Always():
            # Prefix operators bind tightest: only an operand that is itself
            # prefix or atomic goes without parentheses.
            bare = _is_atomic(f.arg) or type(f.arg) in style.prefix
            return [style.prefix[type(f)], *((f.arg,) if bare else ("(", f.arg, ")"))]
        case And(args=args) | Or(args=args):
            pieces: list[str | Formula] = []
            for index, operand in enumerate(args):
                if index:
                    pieces.append(style.infix[type(f)])
                pieces += _operand(operand, style)
            return pieces
    return [*_operand(f.left, style), style.infix[type(f)], *_operand(f.right, style)]


def _operand(f: Formula, style: _Style) -> tuple[str | Formula, ...]:
    """An operand of an infix operator: parenthesised unless atomic or prefix.

    Spot's precedences would allow fewer parentheses, but ``a ∧ b ∨ c`` or
    ``a 𝒰 b 𝒰 c`` make a reader stop and think; the parentheses are cheap.
    """
    if _is_atomic(f) or type(f) in style.prefix:
        return (f,)
    return ("(", f, ")")


def _formula_repr(f: Formula) -> str:
    if f.size > MAX_PRINTED_NODES:  # a repr never raises
        return f"<{type(f).__name__} of {f.size:,} nodes>"
    return f"<{type(f).__name__} {to_spot(f)}>"


# The syntax never imports its printers (ast.py knows nothing of text); the printer lends every formula its
# str (Unicode) and repr (Spot). The package's __init__ imports this module, so any use of cook2ltl.ltl has them.
Formula.__str__ = to_unicode  # type: ignore[method-assign]
Formula.__repr__ = _formula_repr  # type: ignore[method-assign]
