"""Parser, printers and the canonical, hash-consed AST."""

import pickle

import pytest
from hypothesis import given, settings

from cook2ltl.ltl.ast import (
    FALSE,
    TRUE,
    Always,
    And,
    Atom,
    Equiv,
    Eventually,
    Implies,
    Next,
    Not,
    Or,
    Release,
    StrongRelease,
    Until,
    WeakNext,
    WeakUntil,
)
from cook2ltl.ltl.parser import LTLSyntaxError, parse
from cook2ltl.ltl.printer import to_spot, to_unicode
from tests.ltl.ltl_testkit import formulas_strategy

a, b, c = Atom("a"), Atom("b"), Atom("c")
knife = Atom("pick_up", ("knife",))
slice_ = Atom("slice", ("tomato", "knife"))


@pytest.mark.parametrize(
    "text, expected",
    [
        ("F a", Eventually(a)),
        ("G a", Always(a)),
        ("X a", WeakNext(a)),
        ("X[!] a", Next(a)),
        ("a U b", Until(a, b)),
        ("a R b", Release(a, b)),
        ("a W b", WeakUntil(a, b)),
        ("a M b", StrongRelease(a, b)),
        ("!a & b | c", Or(And(Not(a), b), c)),
        ("a -> b", Implies(a, b)),
        ("a <-> b", Equiv(a, b)),
        ("true", TRUE),
        ("false", FALSE),
        ("1 & a", a),
        ("0 | a", a),
        ("GFa", Always(Eventually(a))),
        ("XX[!]a", WeakNext(Next(a))),
        ("a && b || c", Or(And(a, b), c)),
        ("a => b", Implies(a, b)),
        ("<>a & []b", And(Eventually(a), Always(b))),
    ],
)
def test_spot_ascii_syntax(text, expected):
    assert parse(text) is expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("◇a", Eventually(a)),
        ("□a", Always(a)),
        ("○a", WeakNext(a)),
        ("○[!]a", Next(a)),
        ("a 𝒰 b", Until(a, b)),
        ("a ∧ b", And(a, b)),
        ("a ∨ b", Or(a, b)),
        ("¬a", Not(a)),
        ("a → b", Implies(a, b)),
        ("a ↔ b", Equiv(a, b)),
        ("⊤ ∧ ⊥", FALSE),
        ("◇(a ∧ ◇b) & G !c", And(Eventually(And(a, Eventually(b))), Always(Not(c)))),
    ],
)
def test_unicode_syntax(text, expected):
    assert parse(text) is expected


def test_precedence_follows_spot():
    assert parse("a & b U c") is And(a, Until(b, c))
    assert parse("F a U b") is Until(Eventually(a), b)
    assert parse("a U b U c") is Until(a, Until(b, c))
    assert parse("a -> b -> c") is Implies(a, Implies(b, c))
    assert parse("a | b & c") is Or(a, And(b, c))


def test_atoms_with_arguments():
    assert parse("pick_up(knife)") is knife
    assert parse('"slice(tomato, knife)"') is slice_
    assert parse("slice(tomato,knife)") is slice_
    assert parse('"add salt"') is Atom("add salt")
    assert parse('"true" & trueish') is And(Atom("true"), Atom("trueish"))
    assert parse("heat(1) & heat(0)") is And(Atom("heat", ("1",)), Atom("heat", ("0",)))
    assert parse("F(pick_up(knife) & F slice(tomato, knife))").atoms == {knife, slice_}


def test_printers():
    f = parse('F(pick_up(knife) & F "slice(tomato, knife)") & G !cold(apple)')
    assert to_unicode(f) == "◇(pick_up(knife) ∧ ◇slice(tomato, knife)) ∧ □¬cold(apple)"
    assert to_spot(f) == 'F("pick_up(knife)" & F"slice(tomato, knife)") & G!"cold(apple)"'
    assert to_spot(parse("X[!]a W (b -> c)")) == "X[!]a W (b -> c)"
    assert to_unicode(parse("X[!]a W (b -> c)")) == "○[!]a 𝒲 (b → c)"
    assert to_unicode(Atom("slice", ("tomato", "chef knife"))) == '"slice(tomato, chef knife)"'


@pytest.mark.parametrize(
    "text, line, column",
    [
        ("F(a", 1, 4),
        ("a &", 1, 4),
        ("a $ b", 1, 3),
        ("F(a,b)", 1, 4),
        ('"f(a,)"', 1, 1),
        ("a\n  & & b", 2, 5),
        ("pick_up(knife", 1, 14),
        ("", 1, 1),
        ("a b", 1, 3),
    ],
)
def test_syntax_errors_carry_position(text, line, column):
    with pytest.raises(LTLSyntaxError) as info:
        parse(text)
    err = info.value
    assert (err.line, err.column) == (line, column)
    assert f"line {line}, column {column}" in str(err)
    assert err.pointer().splitlines()[-1].index("^") == column + 1  # two-space indent


def test_hash_consing_and_canonical_form():
    assert Atom("a") is a
    assert And(a, b) is And(b, a) is And(a, And(b, a))
    assert Or(a, FALSE) is a and Or(a, TRUE) is TRUE
    assert And() is TRUE and Or() is FALSE
    assert Not(Not(a)) is a and Not(TRUE) is FALSE
    assert pickle.loads(pickle.dumps(Eventually(And(a, knife)))) is Eventually(And(a, knife))
    with pytest.raises(AttributeError):
        a.name = "b"


@pytest.mark.parametrize("bad", ["", " a", "f(x)", 'say"hi"', "a,b"])
def test_atom_rejects_unprintable_names(bad):
    with pytest.raises(ValueError):
        Atom(bad)


@settings(max_examples=300, deadline=None)
@given(formulas_strategy())
def test_round_trip_unicode(f):
    assert parse(to_unicode(f)) is f


@settings(max_examples=300, deadline=None)
@given(formulas_strategy())
def test_round_trip_spot(f):
    assert parse(to_spot(f)) is f
