"""Read LTLf formulas written in Spot's ASCII syntax or in Unicode.

``parse("F(pick_up(knife) & F \\"slice(tomato, knife)\\")")`` builds the
canonical AST of :mod:`cook2ltl.ltl.ast`. Bad input raises
:class:`LTLSyntaxError`, which carries the line and column of the fault.
"""

from __future__ import annotations

from functools import lru_cache
from importlib import resources

from lark import Lark, Token, Transformer, v_args
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput

from cook2ltl.ltl.ast import (
    FALSE, TRUE, Always, And, Atom, Equiv, Eventually, Formula, Implies, Next, Not, Or, Release, StrongRelease,
    Until, WeakNext, WeakUntil,
)
from cook2ltl.ltl.limits import MAX_FORMULA_CHARS, FormulaTooLarge

_UNARY = {
    "X[!]": Next, "○[!]": Next,
    "X": WeakNext, "○": WeakNext,
    "F": Eventually, "◇": Eventually, "<>": Eventually,
    "G": Always, "□": Always, "[]": Always,
    "!": Not, "¬": Not,
}  # fmt: skip
_BINARY = {
    "U": Until, "𝒰": Until,
    "R": Release, "ℛ": Release,
    "W": WeakUntil, "𝒲": WeakUntil,
    "M": StrongRelease, "ℳ": StrongRelease,
}  # fmt: skip

# What the lexer's terminal names mean to a person reading an error.
_TERMINAL_WORDS = {
    "NAME": "an atom",
    "QUOTED": "a quoted atom",
    "ARG": "an argument",
    "UNOP": "a prefix operator",
    "BINOP": "U, R, W or M",
    "LPAR": "'('",
    "RPAR": "')'",
    "COMMA": "','",
    "AND": "'&'",
    "OR": "'|'",
    "IMPLIES": "'->'",
    "EQUIV": "'<->'",
    "TRUE": "true",
    "FALSE": "false",
    "$END": "end of input",
}


class LTLSyntaxError(ValueError):
    """A formula that cannot be read; ``line`` and ``column`` count from 1."""

    def __init__(self, message: str, text: str, line: int, column: int):
        self.text = text
        self.line = line
        self.column = column
        self.reason = message
        super().__init__(f"line {line}, column {column}: {message}\n{self.pointer()}")

    def pointer(self) -> str:
        """The faulty line with a caret under the fault; of a long line, the part around it."""
        lines = self.text.splitlines() or [""]
        source = lines[min(self.line, len(lines)) - 1]
        fault = self.column - 1
        start, end = max(0, fault - _CONTEXT), fault + _CONTEXT
        before, after = ("…" if start else ""), ("…" if len(source) > end else "")
        return f"  {before}{source[start:end]}{after}\n  {' ' * (len(before) + fault - start)}^"


# Characters of a long line shown either side of a fault, and of a long token.
_CONTEXT = 40


def _clip(text: str) -> str:
    return text if len(text) <= _CONTEXT else text[: _CONTEXT - 1] + "…"


class _Bad(ValueError):
    """Raised inside the transformer; carries the token where it went wrong."""

    def __init__(self, message: str, token: Token):
        super().__init__(message)
        self.token = token


def atom_from_text(content: str) -> Atom:
    """``"slice(tomato, knife)"`` (without the quotes) -> ``Atom("slice", ("tomato", "knife"))``."""
    content = content.strip()
    name, args = content, ()
    if content.endswith(")") and "(" in content:
        name, _, inner = content[:-1].partition("(")
        name = name.strip()
        args = tuple(a.strip() for a in inner.split(",")) if inner.strip() else ()
    return Atom(name, args)


@v_args(inline=True)
class _Build(Transformer):
    def start(self, f):
        return f

    def true(self, _):
        return TRUE

    def false(self, _):
        return FALSE

    def plain_atom(self, name, *args):
        return Atom(str(name), tuple(str(a) for a in args if a is not None))

    def quoted_atom(self, token):
        try:
            return atom_from_text(token[1:-1])
        except ValueError as err:
            raise _Bad(f"bad quoted atom {_clip(token)}: {_clip(str(err))}", token) from None

    def unary(self, op, arg):
        return _UNARY[str(op)](arg)

    def binary(self, left, op, right):
        return _BINARY[str(op)](left, right)

    def and_(self, *operands_and_ops):
        return And(*operands_and_ops[::2])

    def or_(self, *operands_and_ops):
        return Or(*operands_and_ops[::2])

    def implies(self, left, _op, right):
        return Implies(left, right)

    def equiv(self, left, _op, right):
        return Equiv(left, right)


@lru_cache(maxsize=1)
def _lark() -> Lark:
    grammar = resources.files("cook2ltl.ltl").joinpath("grammar.lark").read_text("utf-8")
    # The transformer runs inside the LALR parse, as each rule is reduced: no
    # tree walk afterwards, so no recursion however deep the formula nests.
    return Lark(grammar, parser="lalr", lexer="contextual", transformer=_Build())


def _describe(expected: set[str]) -> str:
    words = sorted({_TERMINAL_WORDS.get(name, name.lower()) for name in expected})
    return ", ".join(words)


def parse(text: str) -> Formula:
    """Parse one formula; raise :class:`LTLSyntaxError` if it is not well formed,
    :class:`~cook2ltl.ltl.limits.FormulaTooLarge` if it is longer than the limit."""
    if len(text) > MAX_FORMULA_CHARS:
        raise FormulaTooLarge(f"the formula has {len(text):,} characters, more than the limit of {MAX_FORMULA_CHARS:,}.")
    try:
        return _lark().parse(text)
    except _Bad as err:
        raise LTLSyntaxError(str(err), text, err.token.line, err.token.column) from None
    except UnexpectedEOF as err:
        raise LTLSyntaxError(
            f"formula ends too early; expected {_describe(set(err.expected))}",
            text,
            *_end_position(text),
        ) from None
    except UnexpectedCharacters as err:
        raise LTLSyntaxError(
            f"unexpected character {text[err.pos_in_stream]!r}", text, err.line, err.column
        ) from None
    except UnexpectedInput as err:  # UnexpectedToken
        token = err.token
        found = "end of input" if token.type == "$END" else repr(_clip(str(token)))
        expected = getattr(err, "accepts", None) or getattr(err, "expected", set())
        at_end = token.type == "$END" or err.line < 1
        line, column = _end_position(text) if at_end else (err.line, err.column)
        raise LTLSyntaxError(
            f"unexpected {found}; expected {_describe(set(expected))}", text, line, column
        ) from None


def _end_position(text: str) -> tuple[int, int]:
    return text.count("\n") + 1, len(text.rsplit("\n", 1)[-1]) + 1
