"""Formulas of any size: deep, wide and blown-up formulas give an answer or FormulaTooLarge, never a
RecursionError, a MemoryError or a hang (issue 16). Sizes are asserted, never times."""

import pytest
import typer
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from cook2ltl.errors import UserError
from cook2ltl.ltl import limits
from cook2ltl.ltl.ast import (
    FALSE,
    TRUE,
    Always,
    And,
    Atom,
    Eventually,
    Formula,
    Next,
    Not,
    Or,
    Until,
    postorder,
)
from cook2ltl.ltl.automaton import AutomatonTooLarge, build_dfa
from cook2ltl.ltl.cli import ltl_app
from cook2ltl.ltl.limits import MAX_FORMULA_CHARS, FormulaTooLarge
from cook2ltl.ltl.order import compare
from cook2ltl.ltl.parser import parse
from cook2ltl.ltl.patterns import avoid, sequenced_visit, then
from cook2ltl.ltl.printer import to_spot, to_unicode
from cook2ltl.ltl.progress import holds, progress, progress_trace
from cook2ltl.ltl.simplify import simplify
from tests.ltl.ltl_testkit import BINARY, UNARY, formulas_strategy, small_atoms

ATOMS = small_atoms(3)
a, b = Atom("a"), Atom("b")


def distinct_nodes(f: Formula) -> int:
    return sum(1 for _ in postorder(f))


app = typer.Typer()  # mounted as in the main CLI
app.add_typer(ltl_app, name="ltl")


def ltl(*args):
    return CliRunner().invoke(app, ["ltl", *args])


# --- the failures found, one by one ------------------------------------------------------------------------------


def test_five_hundred_nested_eventually_progress_and_print():
    f = parse("F" * 500 + "a")
    assert progress(f, {a}) is TRUE
    assert progress(f, set()) is Eventually(a)  # ◇◇φ is ◇φ
    assert parse(to_spot(f)) is f and parse(to_unicode(f)) is f
    result = ltl("progress", "F" * 500 + "a", "a")
    assert result.exit_code == 0 and "Trace as a whole: satisfied" in result.stdout


def test_a_conjunction_of_thousands_of_operands():
    text = " & ".join(f"a{i}" for i in range(2000))
    f = parse(text)
    assert isinstance(f, And) and len(f.args) == 2000
    assert parse(to_spot(f)) is f
    assert progress(f, {Atom(f"a{i}") for i in range(2000)}) is TRUE
    assert progress(f, {Atom(f"a{i}") for i in range(1999)}) is FALSE
    built = And(*(Always(Atom(f"p{i}")) for i in range(5000)))  # past the text limit, through the constructors
    assert progress(built, {Atom("p7")}) is FALSE
    assert Or(*built.args).args == built.args  # both sorted the same way


def test_thousands_of_nested_parentheses_and_operators():
    assert parse("(" * 3000 + "a" + ")" * 3000) is a
    nested = parse("".join(f"(a{i} & " for i in range(1500)) + "z" + ")" * 1500)
    assert isinstance(nested, And) and len(nested.args) == 1501
    chain = parse(" U ".join(f"a{i}" for i in range(2000)))
    assert chain.size == 3999 and parse(to_unicode(chain)) is chain
    deep, twin = Eventually(a), Eventually(b)
    for _ in range(20_000):
        deep, twin = Next(Always(deep)), Next(Always(twin))
    assert distinct_nodes(deep) == 40_002
    assert progress(deep, set()) is And(deep.arg, Eventually(TRUE))  # X[!] peels one level
    assert compare(deep, twin) == -1 and compare(twin, deep) == 1  # they differ 40 000 levels down
    assert And(twin, deep).args == (deep, twin)


def test_nested_equivalences_under_eventually_stay_small():
    # The 223-character formula of the report: the progressed formula doubled at every nested <->.
    text = "F" + "".join("(F" for _ in range(20)) + "a" + "".join(f" <-> Fb{i})" for i in range(1, 21))
    assert len(text) > 200
    f = progress(parse(text), {Atom("b1")})
    assert f.size < 2_000 and parse(to_spot(f)) is f  # was 2¹⁹ nodes written out: each <-> doubled it
    for i in range(2, 7):
        f = progress(f, {Atom(f"b{i}")})
        assert distinct_nodes(f) <= 300  # the subformulas of the input, each with its progression
    try:
        assert parse(to_spot(f)) is f
    except FormulaTooLarge as error:  # written out, shared parts repeat: refused, not a hang
        assert "nodes written out" in error.message


def test_printing_a_formula_too_large_to_write_out_is_refused():
    f = a
    for i in range(30):  # each level shares its operand twice: 2³⁰ nodes written out
        f = And(Eventually(And(f, Atom(f"x{i}"))), Eventually(And(f, Atom(f"y{i}"))))
    assert distinct_nodes(f) < 300 and f.size > limits.MAX_PRINTED_NODES
    for write in (to_spot, to_unicode, str):
        with pytest.raises(FormulaTooLarge) as error:
            write(f)
        assert "\n" not in error.value.message and error.value.hint
    assert "nodes>" in repr(f)  # a repr never raises
    assert progress(f, {Atom("x29")}) is not f  # progression works on the shared form


def test_text_over_the_limit_is_refused_by_parser_and_cli():
    text = "a & " * (MAX_FORMULA_CHARS // 4) + "a"
    with pytest.raises(FormulaTooLarge):
        parse(text)
    error = ltl("parse", text).exception
    assert isinstance(error, UserError) and "\n" not in error.message and "20,000" in error.message


def test_a_step_past_the_work_limit_is_refused(monkeypatch):
    f = parse(" U ".join(f"a{i}" for i in range(600)))
    monkeypatch.setattr(limits, "MAX_WORK", 1_000)
    with pytest.raises(FormulaTooLarge, match="progressing the formula by one step"):
        progress(f, {Atom(f"a{i}") for i in range(599)})
    with pytest.raises(FormulaTooLarge, match="simplifying"):
        simplify(f)
    error = ltl("progress", " U ".join(f"a{i}" for i in range(600)), "; ".join(f"a{i}" for i in range(599)))
    assert isinstance(error.exception, UserError) and error.exception.hint


def test_syntax_errors_in_long_lines_show_only_the_part_around_the_fault():
    with pytest.raises(ValueError) as error:
        parse(" & ".join(f"a{i}" for i in range(2000)) + " & )")
    assert len(str(error.value)) < 400 and str(error.value).endswith("^")


def test_automaton_clause_bound():
    f = And(*(Or(Atom(f"p{i}"), Atom(f"q{i}")) for i in range(12)))  # 4096 clauses
    with pytest.raises(AutomatonTooLarge):
        build_dfa(f)
    assert issubclass(AutomatonTooLarge, FormulaTooLarge)


def test_patterns_with_thousands_of_elements():
    actions = [Atom("do", (str(i),)) for i in range(3000)]
    avoided = sequenced_visit(a, *(avoid(x) for x in actions), b)  # "do not …" 3000 times in a row
    assert holds(avoided, [{a}, {b}]) and not holds(avoided, [{a}, {actions[5]}, {b}])
    nested = actions[0]
    for x in actions[1:]:
        nested = then(nested, x)
    f = sequenced_visit(nested)
    assert f is sequenced_visit(*actions)
    assert progress_trace(f, [{x} for x in actions]) is TRUE


def test_rollout_walks_and_progresses_huge_and_deep_formulas():
    from cook2ltl.execution.rollout import choose, in_order

    pick = Atom("pick_up", ("apple",))
    deep = parse("F" * 2000 + "pick_up(apple)")
    assert in_order(deep) == [pick]
    assert choose(deep, frozenset(), (pick,)) == ([pick], None)
    shared = pick
    for i in range(40):  # 2⁴⁰ nodes written out
        shared = Or(Eventually(And(shared, Atom("open", (f"d{i}",)))), Until(Not(pick), shared))
    assert len(in_order(shared)) == 41


# --- properties --------------------------------------------------------------------------------------------------

small = formulas_strategy(atoms=st.sampled_from(ATOMS), max_leaves=4)
# A layer wraps the formula in a prefix operator, or puts it beside a small one under a binary operator.
layer = st.one_of(st.sampled_from(UNARY), st.tuples(st.sampled_from(BINARY), small, st.booleans()))


def deepen(leaf: Formula, pattern: list, times: int) -> Formula:
    f = leaf
    for _ in range(times):
        for wrap in pattern:
            if isinstance(wrap, type):
                f = wrap(f)
            else:
                op, other, left = wrap
                f = op(f, other) if left else op(other, f)
    return f


deep_formulas = st.builds(deepen, small, st.lists(layer, min_size=1, max_size=4), st.integers(1, 1500))
steps = st.lists(st.frozensets(st.sampled_from(ATOMS)), max_size=4)
DEEP = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@DEEP
@given(deep_formulas)
def test_deep_formulas_print_and_read_back(f):
    for write in (to_spot, to_unicode):
        text = write(f)
        if len(text) <= MAX_FORMULA_CHARS:
            assert parse(text) is f
        else:
            with pytest.raises(FormulaTooLarge):
                parse(text)


@DEEP
@given(deep_formulas, steps)
def test_deep_formulas_progress_within_the_bound_or_are_refused(f, trace):
    for step in trace:
        try:
            progressed = progress(f, step)
        except FormulaTooLarge:
            return
        assert distinct_nodes(progressed) <= distinct_nodes(f) + limits.MAX_WORK
        f = progressed


@DEEP
@given(deep_formulas, deep_formulas)
def test_deep_formulas_sort_and_simplify(f, g):
    assert compare(f, g) == -compare(g, f) and (compare(f, g) == 0) == (f is g)
    assert And(f, g) is And(g, f)
    try:
        simplify(And(f, g))
    except FormulaTooLarge:
        pass


@settings(max_examples=300, deadline=None)
@given(formulas_strategy(atoms=st.sampled_from(ATOMS), max_leaves=16), steps)
def test_progression_grows_a_formula_at_most_linearly_per_step(f, trace):
    for step in trace:
        progressed = progress(f, step)
        assert distinct_nodes(progressed) <= 4 * distinct_nodes(f) + 4, (f, step, progressed)
        f = progressed


def legacy_key(f: Formula) -> tuple:
    """The nested-tuple sort key the canonical order used to be (recursive: small formulas only)."""
    if f is TRUE or f is FALSE:
        return (0, f.value)
    if isinstance(f, Atom):
        return (1, f.name, f.args)
    if isinstance(f, (And, Or)):
        return (f.rank, tuple(legacy_key(x) for x in f.args))
    return (f.rank, *(legacy_key(x) for x in f.children))


@settings(max_examples=300, deadline=None)
@given(small, small)
def test_the_canonical_order_is_the_lexicographic_order_of_operators_and_operands(f, g):
    want = (legacy_key(f) > legacy_key(g)) - (legacy_key(f) < legacy_key(g))
    assert compare(f, g) == want
