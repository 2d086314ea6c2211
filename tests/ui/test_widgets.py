"""The pieces of the screens that draw core records, without a running app."""

from __future__ import annotations

from cook2ltl.ltl import parse
from cook2ltl.ltl.ast import Atom
from cook2ltl.ui.feeds import object_states
from cook2ltl.ui.widgets.progress_view import MET_STYLE, marked


def marked_texts(formula: str, met: set[Atom]) -> list[str]:
    content = marked(parse(formula), frozenset(met))
    return sorted(content.plain[span.start:span.end] for span in content.spans if span.style == MET_STYLE)


def test_every_occurrence_of_a_met_atom_is_marked_and_nothing_else():
    formula = "F(open(fridge) & F(pick_up(apple) & F(close(fridge) & F open(fridge))))"
    assert marked_texts(formula, {Atom("open", ("fridge",)), Atom("pick_up", ("apple",))}) == [
        "open(fridge)", "open(fridge)", "pick_up(apple)"]


def test_an_atom_without_arguments_is_not_marked_inside_another_atom():
    assert marked_texts("F(fridge & F open(fridge))", {Atom("fridge")}) == ["fridge"]
    assert marked_texts("wait U hot(potato)", {Atom("wait")}) == ["wait"]


def test_object_states_in_the_order_first_touched_and_pieces_that_are_gone():
    objects = [
        {"objectId": "Fridge|1", "objectType": "Fridge", "openable": True, "isOpen": False, "temperature": "Cold"},
        {"objectId": "Apple|2", "objectType": "Apple", "parentReceptacles": ["Fridge|1"], "isSliced": True},
        {"objectId": "Mug|3", "isPickedUp": True, "isFilledWithLiquid": True, "fillLiquid": "coffee"},
    ]
    states = object_states(objects, ["Apple|2", "Fridge|1", "Mug|3", "Bread|4"])
    assert [(s.name, s.where, s.state) for s in states] == [
        ("Apple", "Fridge", "sliced"), ("Fridge", "", "closed, cold"), ("Mug", "in hand", "filled with coffee"),
        ("Bread", "", "gone (sliced or broken into pieces)")]


def test_a_formula_too_large_to_print_is_noted_not_drawn(monkeypatch):
    """The app never fails drawing a formula: one past the printer's limit shows as too large."""
    import cook2ltl.ltl.printer as printer
    from cook2ltl.ltl.parser import parse
    from cook2ltl.ui.literal import formula_text, shown_formula

    formula = parse("F(a & F(b & F c))")
    assert formula_text(formula) == "◇(a ∧ ◇(b ∧ ◇c))"
    monkeypatch.setattr(printer, "MAX_PRINTED_NODES", 3)
    assert formula_text(formula) is None and formula_text(formula, spot=True) is None
    assert shown_formula(formula).plain == "(too large to show)"


def test_a_reused_entry_says_where_it_came_from():
    """A library hit learnt for another verb or signature is marked reused, and its detail names the entry and why."""
    from cook2ltl.domain.actions import Action, Call, Parameter, Reduction, Source
    from cook2ltl.library.reuse import Reuse
    from cook2ltl.pipeline.records import ActionResult
    from cook2ltl.ui.widgets.reductions import reduction_label, result_detail

    action = Action("stir_in", (Parameter("what", "the sugar", "sugar", "sugar"),))
    plan = (Call("stir", ("sugar",)),)
    cached = ActionResult(0, Reduction(action, plan, Source.LIBRARY, entry_id=3), plan)
    reused = ActionResult(0, Reduction(action, plan, Source.LIBRARY, entry_id=3), plan,
                          reuse=Reuse(3, "stir", ("what",), ("the verb-effect table reads stir_in as stir",)))
    assert reduction_label(cached).plain == "cached #3" and reduction_label(reused).plain == "reused #3"
    assert "reused entry 3 stir(what): the verb-effect table reads stir_in as stir" in result_detail(reused).plain
    assert "reused" not in result_detail(cached).plain
