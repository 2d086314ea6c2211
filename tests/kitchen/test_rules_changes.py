"""Slicing, breaking, cooking, liquids and dirt."""

EGG_IN_FRIDGE = "Egg|-02.04|+00.81|+01.24"


def test_slicing_with_a_knife_replaces_the_object_by_its_pieces(bench):
    tomato = bench["Tomato"]
    bench.hold("Knife")
    result = bench.do("SliceObject", tomato.object_id)
    pieces = [f"{tomato.object_id}|TomatoSliced_{n}" for n in range(7)]
    assert result.action_return == pieces
    assert tomato.object_id not in bench.state.objects
    for piece in pieces:
        thing = bench[piece]
        assert thing.object_type == "TomatoSliced" and thing.parent == tomato.parent
        assert thing.can("pickupable") and not thing.can("cookable")


def test_slicing_refused_without_a_knife_in_hand(bench):
    bench.refuse("SliceObject", "Tomato", match="needs a ButterKnife or Knife in hand; the agent holds nothing")
    bench.hold("Apple")
    bench.refuse("SliceObject", "Tomato", match="the agent holds Apple")


def test_a_butter_knife_cuts_too(bench):
    bench.hold("ButterKnife")
    bench.do("SliceObject", "Bread")
    assert bench["BreadSliced"].can("cookable")


def test_the_knife_rule_can_be_switched_off(bench):
    bench.state = bench.state.evolve(slice_needs_knife=False)
    bench.do("SliceObject", "Lettuce")
    assert bench["LettuceSliced"]


def test_slicing_refused_for_unsliceable_held_or_shut_away_objects(bench):
    bench.hold("Knife")
    bench.refuse("SliceObject", "Pan", match="cannot be sliced")
    bench.refuse("SliceObject", EGG_IN_FRIDGE, match="inside the closed Fridge")
    bench.state = bench.state.evolve(slice_needs_knife=False)
    bench.hold("Apple")
    bench.refuse("SliceObject", "Apple", match="Put Apple")


def test_slices_keep_the_cooked_state_and_temperature(bench):
    bench.do("CookObject", "Potato")
    bench.hold("Knife")
    bench.do("SliceObject", "Potato")
    assert bench["PotatoSliced"].is_cooked


def test_breaking_marks_the_object_broken_and_spills_its_liquid(bench):
    bench.do("FillObjectWithLiquid", "Mug", fillLiquid="water")
    bench.do("BreakObject", "Mug")
    mug = bench["Mug"]
    assert mug.is_broken and not mug.is_filled and mug.fill_liquid is None


def test_breaking_refused_when_broken_or_unbreakable(bench):
    bench.do("BreakObject", "Vase")
    bench.refuse("BreakObject", "Vase", match="already broken")
    bench.refuse("BreakObject", "Pan", match="cannot be broken")


def test_breaking_an_egg_cracks_it(bench):
    result = bench.do("BreakObject", EGG_IN_FRIDGE, forceAction=True)
    assert result.action_return == [f"{EGG_IN_FRIDGE}|EggCracked_0"]
    cracked = bench["EggCracked"]
    assert cracked.can("cookable") and cracked.temperature == "Cold"


def test_breaking_a_held_egg_is_refused_as_cutting_it_is(bench):
    # Breaking an egg splits it: in the hand, the hand would hold the removed egg.
    bench.hold(EGG_IN_FRIDGE)
    bench.refuse("BreakObject", EGG_IN_FRIDGE, match=f"Put {EGG_IN_FRIDGE} down before breaking it")
    bench.do("PutObject", "Bowl")
    bench.do("PickupObject", "Bowl")
    bench.refuse("BreakObject", EGG_IN_FRIDGE, match="down before breaking")  # nor in what the hand holds
    bench.do("PutObject", "CounterTop")
    bench.do("BreakObject", EGG_IN_FRIDGE)
    assert bench["EggCracked"].parent == bench.id("Bowl") and bench.state.held is None


def test_cook_object(bench):
    bench.do("CookObject", "Potato")
    assert bench["Potato"].is_cooked
    bench.refuse("CookObject", "Potato", match="already cooked")
    bench.refuse("CookObject", "Apple", match="cannot be cooked")


def test_fill_and_empty(bench):
    bench.do("FillObjectWithLiquid", "Mug", fillLiquid="coffee")
    assert bench["Mug"].fill_liquid == "coffee"
    bench.refuse("FillObjectWithLiquid", "Mug", match="already filled with coffee", fillLiquid="water")
    bench.do("EmptyLiquidFromObject", "Mug")
    assert not bench["Mug"].is_filled
    bench.refuse("EmptyLiquidFromObject", "Mug", match="already empty")


def test_fill_checks_its_arguments_and_the_object(bench):
    bench.refuse("FillObjectWithLiquid", "Mug", match="needs a fillLiquid", code="MissingArguments")
    bench.refuse("FillObjectWithLiquid", "Mug", match="must be one of", code="InvalidArgument", fillLiquid="milk")
    bench.refuse("FillObjectWithLiquid", "Apple", match="cannot hold liquid", fillLiquid="water")
    bench.refuse("EmptyLiquidFromObject", "Apple", match="cannot hold liquid")


def test_dirty_and_clean(bench):
    bench.do("DirtyObject", "Bowl")
    assert bench["Bowl"].is_dirty
    bench.refuse("DirtyObject", "Bowl", match="already dirty")
    bench.do("CleanObject", "Bowl")
    assert not bench["Bowl"].is_dirty
    bench.refuse("CleanObject", "Bowl", match="already clean")
    bench.refuse("DirtyObject", "Apple", match="cannot get dirty")
