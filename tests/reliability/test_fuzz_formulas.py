"""Fuzzing target: hostile LTL formula text (very long, very deep, every operator in ASCII and Unicode, junk)
through the parser, the printers, progression and the `ltl` CLI. Each gives a result or a clean error
(LTLSyntaxError, FormulaTooLarge, or a UserError at the CLI), never another exception or a hang."""

import typer
from hypothesis import given
from hypothesis import strategies as st
from typer.testing import CliRunner

from cook2ltl.errors import UserError
from cook2ltl.ltl.ast import Atom, Formula
from cook2ltl.ltl.cli import ltl_app
from cook2ltl.ltl.limits import MAX_FORMULA_CHARS, FormulaTooLarge
from cook2ltl.ltl.parser import LTLSyntaxError, parse
from cook2ltl.ltl.printer import to_spot, to_unicode
from cook2ltl.ltl.progress import Verdict, monitor
from tests.reliability.hostile import FUZZ, TRIED

OPERATORS = ["F", "G", "X", "X[!]", "U", "R", "W", "M", "!", "&", "|", "->", "<->", "<=>", "=>", "&&", "||",
             "/\\", "\\/", "◇", "□", "○", "○[!]", "𝒰", "ℛ", "𝒲", "ℳ", "∧", "∨", "¬", "→", "↔", "[]", "<>",
             "⊤", "⊥", "true", "false", "1", "0"]
ATOMS = ["a", "b", "pick_up(knife)", '"slice(tomato, knife)"', "x_1", "trueish", "put(egg, pan)", '"Add salt"']
JUNK = ["(", ")", ",", '"', "\n", " ", "\t", "\u200b", "\u202e", "\x00", "é", "Ω", "🍳", "[", "]", "[!]", "X[",
        "\\", "$", "()", '""', "a(", "a(,)"]
piece = st.sampled_from(OPERATORS + ATOMS + JUNK)
atom = st.sampled_from(ATOMS)
# (opening, closing) repeated around an atom: deep nestings, well formed or not.
NESTINGS = [("F", ""), ("G", ""), ("X[!]", ""), ("!", ""), ("¬◇", ""), ("(", ")"), ("F(", ")"), ("(a & ", ")"),
            ("(a <-> F", ")"), ("(F", " <-> F b)"), ("(b U ", ")"), ("a R (", ")"), ("○[!](", ""), ("(", "")]
SEPARATORS = [" & ", " | ", " U ", " R ", " -> ", " <-> ", " ∧ ", " ∨ ", " 𝒲 ", "", " "]

deep = st.builds(lambda nesting, n, leaf: nesting[0] * n + leaf + nesting[1] * n,
                 st.sampled_from(NESTINGS), st.integers(1, 4000), atom)
long = st.builds(lambda parts, separator, n: separator.join(parts * n),
                 st.lists(st.one_of(atom, piece), min_size=1, max_size=4), st.sampled_from(SEPARATORS),
                 st.integers(1, 3000))
formula_text = st.one_of(
    st.text(max_size=200),
    st.text(alphabet=st.characters(codec="utf-8"), max_size=100),
    st.lists(piece, max_size=80).map(" ".join),
    st.lists(piece, max_size=80).map("".join),
    deep,
    long,
    st.tuples(st.one_of(deep, long), st.sampled_from(SEPARATORS), st.one_of(deep, long, atom)).map("".join),
)


def parsed(text: str) -> Formula | None:
    """The formula, or None when the parser refused it cleanly."""
    try:
        return parse(text)
    except LTLSyntaxError as error:
        assert error.line >= 1 and error.column >= 1 and len(error.pointer()) < 200
    except FormulaTooLarge as error:
        assert len(text) > MAX_FORMULA_CHARS and "\n" not in error.message and error.hint
    return None


@FUZZ
@given(formula_text)
def test_hostile_formula_text_parses_or_is_refused_cleanly(text):
    TRIED["ltl parse"] += 1
    f = parsed(text)
    assert f is None or isinstance(f, Formula)


@FUZZ
@given(formula_text, st.data())
def test_hostile_formulas_progress_or_are_refused_cleanly(text, data):
    TRIED["ltl progress"] += 1
    f = parsed(text)
    if f is None:
        return
    known = sorted(f.atoms, key=lambda x: x.key) + [Atom("other")]
    trace = data.draw(st.lists(st.frozensets(st.sampled_from(known)), max_size=6))
    try:
        for result in monitor(f, trace):
            assert isinstance(result.remaining, Formula) and isinstance(result.verdict, Verdict)
    except FormulaTooLarge as error:
        assert "\n" not in error.message and error.hint


@FUZZ
@given(formula_text)
def test_hostile_formulas_print_and_read_back(text):
    TRIED["ltl print"] += 1
    f = parsed(text)
    if f is None:
        return
    for write in (to_spot, to_unicode):
        try:
            written = write(f)
        except FormulaTooLarge as error:
            assert "\n" not in error.message
            continue
        if len(written) > MAX_FORMULA_CHARS:
            assert parsed(written) is None
        else:
            assert parse(written) is f


app = typer.Typer()  # mounted as in the main CLI
app.add_typer(ltl_app, name="ltl")


@FUZZ
@given(formula_text, st.lists(st.one_of(atom, piece), max_size=3).map("; ".join))
def test_hostile_formulas_through_the_ltl_cli(text, step):
    TRIED["ltl cli"] += 1
    for command in (["parse", text], ["progress", text, step, "-"], ["progress", text, "--json"]):
        result = CliRunner().invoke(app, ["ltl", *command])
        assert result.exception is None or isinstance(result.exception, (UserError, SystemExit)), result.exception
