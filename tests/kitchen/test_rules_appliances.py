"""Opening, switching, and what heat and cold sources do to their contents."""

FRIDGE = "Fridge|-02.10|+00.00|+01.07"
MICROWAVE = "Microwave|-00.24|+01.69|-02.53"
KNOB = "StoveKnob|-00.02|+00.88|-02.19"
BURNER = "StoveBurner|-00.04|+00.92|-02.37"  # the one KNOB switches


def test_open_and_close_an_openable(bench):
    bench.do("OpenObject", FRIDGE)
    assert bench[FRIDGE].is_open and bench[FRIDGE].openness == 1.0
    bench.do("CloseObject", FRIDGE)
    assert not bench[FRIDGE].is_open


def test_open_refused_when_open_or_not_openable(bench):
    bench.do("OpenObject", FRIDGE)
    bench.refuse("OpenObject", FRIDGE, match="already open")
    bench.refuse("OpenObject", "CounterTop", match="cannot be opened")


def test_open_checks_openness(bench):
    bench.refuse("OpenObject", FRIDGE, match="openness", code="InvalidArgument", openness=1.5)
    bench.do("OpenObject", FRIDGE, openness=0.5)
    assert bench[FRIDGE].openness == 0.5


def test_close_refused_when_closed_or_not_openable(bench):
    bench.refuse("CloseObject", FRIDGE, match="already closed")
    bench.refuse("CloseObject", "CounterTop", match="cannot be closed")


def test_microwave_must_be_closed_to_turn_on(bench):
    bench.do("OpenObject", MICROWAVE)
    bench.refuse("ToggleObjectOn", MICROWAVE, match="close it before turning it on")
    bench.do("CloseObject", MICROWAVE)
    bench.do("ToggleObjectOn", MICROWAVE)
    assert bench[MICROWAVE].is_toggled


def test_microwave_must_be_off_to_open(bench):
    bench.do("ToggleObjectOn", MICROWAVE)
    bench.refuse("OpenObject", MICROWAVE, match="turn it off before opening")
    bench.do("ToggleObjectOff", MICROWAVE)
    bench.do("OpenObject", MICROWAVE)


def test_toggle_refused_when_already_in_that_state_or_not_toggleable(bench):
    bench.refuse("ToggleObjectOff", MICROWAVE, match="already off")
    bench.do("ToggleObjectOn", MICROWAVE)
    bench.refuse("ToggleObjectOn", MICROWAVE, match="already on")
    bench.refuse("ToggleObjectOn", "Apple", match="cannot be switched")


def test_burners_are_switched_through_their_knobs(bench):
    bench.refuse("ToggleObjectOn", BURNER, match=f"switched by {KNOB}")
    bench.do("ToggleObjectOn", KNOB)
    assert bench[BURNER].is_toggled
    bench.do("ToggleObjectOff", KNOB)
    assert not bench[BURNER].is_toggled


def test_a_lit_burner_heats_and_cooks_what_is_in_the_pan_on_it(bench):
    bench.hold("Potato")
    bench.do("PutObject", "Pan")
    bench.hold("Pan")
    bench.do("PutObject", BURNER)
    assert bench["Potato"].temperature == "RoomTemp" and not bench["Potato"].is_cooked
    bench.do("ToggleObjectOn", KNOB)
    assert bench["Pan"].temperature == "Hot"
    assert bench["Potato"].temperature == "Hot" and bench["Potato"].is_cooked


def test_putting_food_into_a_running_heat_source_cooks_it_at_once(bench):
    bench.hold("Pan")
    bench.do("PutObject", BURNER)
    bench.do("ToggleObjectOn", KNOB)
    bench.hold("Potato")
    bench.do("PutObject", "Pan")
    assert bench["Potato"].is_cooked


def test_a_cold_burner_heats_nothing(bench):
    bench.hold("Pan")
    bench.do("PutObject", BURNER)
    bench.hold("Potato")
    bench.do("PutObject", "Pan")
    assert bench["Potato"].temperature == "RoomTemp" and not bench["Potato"].is_cooked


def test_microwaving_heats_everything_but_only_cooks_cookables(bench):
    bench.do("OpenObject", MICROWAVE)
    for food in ("Potato", "Apple"):
        bench.hold(food)
        bench.do("PutObject", MICROWAVE)
    bench.do("CloseObject", MICROWAVE)
    bench.do("ToggleObjectOn", MICROWAVE)
    assert bench["Potato"].temperature == "Hot" and bench["Potato"].is_cooked
    assert bench["Apple"].temperature == "Hot" and not bench["Apple"].is_cooked


def test_the_toaster_toasts_bread_slices(bench):
    bench.hold("Knife")
    bench.do("SliceObject", "Bread")
    bench.hold("BreadSliced")
    bench.do("PutObject", "Toaster")
    bench.do("ToggleObjectOn", "Toaster")
    assert bench["BreadSliced"].is_cooked and bench["BreadSliced"].temperature == "Hot"


def test_a_running_coffee_machine_fills_the_mug_with_hot_coffee(bench):
    bench.hold("Mug")
    bench.do("PutObject", "CoffeeMachine")
    assert not bench["Mug"].is_filled
    bench.do("ToggleObjectOn", "CoffeeMachine")
    mug = bench["Mug"]
    assert mug.is_filled and mug.fill_liquid == "coffee" and mug.temperature == "Hot"


def test_the_fridge_chills_what_is_put_in_it(bench):
    bench.do("OpenObject", FRIDGE)
    bench.hold("Apple")
    bench.do("PutObject", FRIDGE)
    assert bench["Apple"].temperature == "Cold"
    assert bench["Tomato"].temperature == "RoomTemp"  # still on the counter


def test_hot_food_cools_in_the_fridge_and_stays_hot_elsewhere(bench):
    bench.do("ToggleObjectOn", MICROWAVE)
    bench.do("ToggleObjectOff", MICROWAVE)
    bench.do("OpenObject", MICROWAVE)
    bench.hold("Potato")
    bench.do("PutObject", MICROWAVE)
    bench.do("CloseObject", MICROWAVE)
    bench.do("ToggleObjectOn", MICROWAVE)
    bench.do("ToggleObjectOff", MICROWAVE)
    bench.do("OpenObject", MICROWAVE)
    bench.hold("Potato")
    bench.do("PutObject", "CounterTop")
    assert bench["Potato"].temperature == "Hot"
    bench.do("OpenObject", FRIDGE)
    bench.hold("Potato")
    bench.do("PutObject", FRIDGE)
    assert bench["Potato"].temperature == "Cold" and bench["Potato"].is_cooked


def test_broken_things_do_not_switch(bench_in):
    phone = bench_in("FloorPlan2")
    phone.do("ToggleObjectOn", "CellPhone")
    phone.do("ToggleObjectOff", "CellPhone")
    phone.do("BreakObject", "CellPhone")
    phone.refuse("ToggleObjectOn", "CellPhone", match="broken")
