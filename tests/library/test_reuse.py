"""library.reuse on its own: which entry of another verb or signature serves an action, how, and why."""

from cook2ltl.domain.actions import Action, Parameter
from cook2ltl.library.entry import LibraryEntry, Status
from cook2ltl.library.reuse import fit_entry, reuses, same_action

ADD = "pick_up($what)\nput($what, $where)"


def act(verb, *slots):
    """An action from (category, value) pairs; a time's name is its text, as the parser writes until_cold."""
    return Action(verb, tuple(Parameter(c, v, f"until_{v}" if c == "time" else v, v) for c, v in slots))


def entry(number, verb, signature, body, status=Status.PENDING):
    return LibraryEntry(number, "recipe", verb, signature, body, status, "scripted", "", "2024-01-01")


def texts(fit):
    return [call.text() for call in fit.body]


def test_the_table_reads_a_verb_without_a_row_as_its_first_words_row():
    assert same_action("stir_in", "stir") == "the verb-effect table reads stir_in as stir"
    assert same_action("stir", "stir_in") == "the verb-effect table reads stir_in as stir"
    assert same_action("stir_in", "stir_up") == "the verb-effect table reads stir_in and stir_up as stir"
    assert same_action("add", "add") == ""
    # a verb with a row of its own is its own action, even beside a row of the same first word and effect
    assert same_action("stir_and_skim", "stir") is None
    assert same_action("simmer", "boil") is None
    assert same_action("zzz_in", "zzz") is None  # neither in the table: only the same verb


def test_one_what_is_distributed_over_several_in_order():
    fit = fit_entry(act("add", ("what", "flour"), ("what", "sugar"), ("what", "salt"), ("where", "bowl")),
                    entry(1, "add", ("what", "where"), ADD))
    assert texts(fit) == ["pick_up(flour)", "put(flour, bowl)", "pick_up(sugar)", "put(sugar, bowl)",
                          "pick_up(salt)", "put(salt, bowl)"]
    assert fit.reuse.reasons == ("distributed over 3 objects: flour, sugar, salt",)
    assert (fit.reuse.entry_id, fit.reuse.verb, fit.reuse.signature) == (1, "add", ("what", "where"))


def test_a_body_binding_every_what_is_bound_once():
    fit = fit_entry(act("mix", ("what", "egg"), ("what", "milk"), ("how", "whisk")),
                    entry(2, "mix", ("what", "what"), "put($what, bowl)\nput($what2, bowl)\nstir($what)"))
    assert texts(fit) == ["put(egg, bowl)", "put(milk, bowl)", "stir(egg)"]
    assert fit.reuse.reasons == ("ignores how: whisk",)


def test_a_what_or_a_where_is_never_left_out_and_a_placeholder_never_left_unbound():
    two = "put($what, bowl)\nput($what2, bowl)"
    assert fit_entry(act("mix", ("what", "egg"), ("what", "milk"), ("what", "flour")), entry(1, "mix", ("what", "what"),
                     two)) is None  # flour would be left out
    assert fit_entry(act("mix", ("what", "egg")), entry(1, "mix", ("what", "what"), two)) is None  # $what2 unbound
    assert fit_entry(act("heat", ("what", "pan")), entry(1, "heat", (), "turn_on(stovetop)")) is None  # pan left out
    assert fit_entry(act("add", ("what", "egg")), entry(1, "add", ("what", "where"), ADD)) is None  # $where unbound
    assert fit_entry(act("add", ("what", "egg"), ("where", "bowl")), entry(1, "add", ("what",), "pick_up($what)")
                     ) is None  # the bowl would be left out


def test_an_entry_whose_body_needs_a_time_does_not_serve_an_action_without_one():
    body = "put($what, fridge)\nwait($what == $time)"
    assert fit_entry(act("chill", ("what", "cream")), entry(1, "chill", ("what", "time"), body)) is None
    fit = fit_entry(act("chill", ("what", "cream"), ("time", "cold")),
                    entry(1, "chill", ("what",), "put($what, fridge)"))
    assert texts(fit) == ["put(cream, fridge)"] and fit.reuse.reasons == ("ignores time: until_cold",)


def test_the_best_entry_first():
    action = act("stir_in", ("what", "sugar"), ("how", "slowly"))
    ranked = reuses(action, [
        entry(1, "stir", ("what",), "stir($what)"),  # another verb of the row
        entry(2, "stir_in", ("what", "how", "where"), "stir($what)"),  # the same verb, ignores how
        entry(3, "stir_in", ("what",), "stir($what)\nstir($what)"),  # the same verb, ignores how: ties, newer
        entry(4, "stir_in", ("what", "how"), "stir($what)\nput($how, sink)"),  # the exact key
        entry(5, "stir_and_skim", ("what",), "stir($what)"),  # its own row: never
    ])
    assert [fit.entry.id for fit in ranked] == [4, 2, 3, 1]
    assert ranked[0].reuse.reasons == ()  # the exact key: nothing to explain
    assert ranked[-1].reuse.reasons == ("the verb-effect table reads stir_in as stir", "ignores how: slowly")
    # fewest ignored arguments before the oldest; a body bound once before one distributed
    assert [f.entry.id for f in reuses(action, [entry(8, "stir_in", ("what",), "stir($what)"),
                                                entry(9, "stir_in", ("what", "where"), "stir($what)\nput($how, sink)")])
            ] == [9, 8]
    two = act("stir_in", ("what", "sugar"), ("what", "salt"))
    assert [f.entry.id for f in reuses(two, [entry(6, "stir_in", ("what",), "stir($what)"),
                                             entry(7, "stir_in", ("what", "what", "how"), "stir($what)\nstir($what2)")])
            ] == [7, 6]


def test_only_live_entries_with_a_plan_and_in_lab_mode_only_approved_ones():
    action = act("stir_in", ("what", "sugar"))
    candidates = [entry(1, "stir", ("what",), "stir($what)", Status.REJECTED),
                  entry(2, "stir", ("what",), "", Status.PENDING),
                  entry(3, "stir", ("what",), "stir($what)", Status.PENDING),
                  entry(4, "stir", ("what",), "pick_up(spoon)\nstir($what)", Status.APPROVED)]
    assert [fit.entry.id for fit in reuses(action, candidates)] == [3, 4]
    assert [fit.entry.id for fit in reuses(action, candidates, approved_only=True)] == [4]


def test_a_body_that_is_not_calls_or_names_an_unknown_placeholder_serves_nothing():
    action = act("add", ("what", "egg"), ("where", "bowl"))
    assert fit_entry(action, entry(1, "add", ("what", "where"), "put($what, $where)\nthis is prose")) is None
    assert fit_entry(action, entry(1, "add", ("what", "where"), "put($what1, $where)")) is None
    assert fit_entry(action, entry(1, "add", ("what", "where"), "put($what, $ingredient)")) is None
