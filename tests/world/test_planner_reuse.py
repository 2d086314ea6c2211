"""A search is done once per problem up to the names of things: boiling the rice after boiling the penne from the
same kitchen asks Fast Downward nothing, and the plan names the rice."""

from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.world import planner
from cook2ltl.world.kitchens import grounding


def test_the_same_search_for_another_ingredient_is_not_done_again(monkeypatch):
    kitchen = grounding(load_primitives("recipe"))
    searches = []
    solve = planner._solve
    monkeypatch.setattr(planner, "_solve", lambda *args: searches.append(args) or solve(*args))
    start = kitchen.start(["penne", "rice", "butter"]).state

    penne = kitchen.planner.plan(kitchen.world, start, (("boiled", "penne"),))
    rice = kitchen.planner.plan(kitchen.world, start, (("boiled", "rice"),))
    assert len(searches) == 1
    assert [c.text() for c in rice] == [c.text().replace("penne", "rice") for c in penne]
    assert any("rice" in c.args for c in rice) and not any("penne" in c.args for c in rice)

    kitchen.planner.plan(kitchen.world, start, (("melted", "butter"),))  # another problem: searched
    assert len(searches) == 2
