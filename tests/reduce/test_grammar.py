"""The GBNF grammar generated per action: it admits the paper's plans and nothing outside 𝒜."""

import re

import pytest

from cook2ltl.domain.actions import Action, Call
from cook2ltl.reduce.action import parameter
from cook2ltl.reduce.body import read_call
from cook2ltl.reduce.grammar import admits, to_gbnf, vocabulary
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.reduce.prompt import example_functions
from tests.reduce.gbnf import accepts

RECIPE = load_primitives("recipe")
THOR = load_primitives("ai2thor")


def action(verb, *params):
    return Action(verb, tuple(parameter(category, text) for category, text in params))


def header_action(function_header: str) -> Action:
    """`def bake(cake: what, oven: where, 30_minutes: time):` back to an action."""
    verb, inside = re.match(r"def (\w+)\((.*)\):", function_header).groups()
    pairs = [part.split(": ") for part in inside.split(", ")]
    return Action(verb, tuple(parameter(category, name.replace("_", " ")) for name, category in pairs))


def body_text(lines):
    return "".join(f"    {line}\n" for line in lines) + "\n"


@pytest.mark.parametrize("primitives, name", [
    (RECIPE, "cook"), (RECIPE, "bake"), (THOR, "refrigerate"), (THOR, "store"),
])
def test_accepts_the_papers_example_bodies(primitives, name, comments=False):
    function_header, body = next((h, b) for h, b in example_functions(primitives) if h.startswith(f"def {name}("))
    vocab = vocabulary(primitives, [], header_action(function_header))
    calls = [line for line in body if not line.startswith("#")]
    assert accepts(to_gbnf(vocab, max_lines=12, comments=False), body_text(calls))
    assert accepts(to_gbnf(vocab, max_lines=12, comments=True), body_text(body))  # with the paper's comments
    assert all(admits(vocab, read_call(line)) for line in calls)


def test_rejects_a_non_primitive_a_wrong_arity_and_unknown_things():
    vocab = vocabulary(RECIPE, [], action("boil", ("what", "the eggs")))
    grammar = to_gbnf(vocab, max_lines=12, comments=False)
    assert accepts(grammar, body_text(["put(eggs, pot)", "turn_on(stovetop)", "wait(eggs == boiled)"]))
    for line in ["fry(eggs)", "put(eggs)", "put(unicorn, pot)", "wait(eggs == exploded)", "boil(eggs)",
                 "pick up(eggs)", "wait(timer == soon)"]:
        assert not accepts(grammar, body_text([line])), line
        call = read_call(line)
        assert call is None or not admits(vocab, call), line


def test_the_number_of_lines_is_capped_and_a_body_is_not_empty():
    grammar = to_gbnf(vocabulary(RECIPE, [], action("stir", ("what", "soup"))), max_lines=3, comments=False)
    assert accepts(grammar, body_text(["stir(soup)"] * 3))
    assert not accepts(grammar, body_text(["stir(soup)"] * 4))
    assert not accepts(grammar, "\n")


def test_the_actions_own_arguments_join_the_vocabulary():
    blend = action("blend", ("what", "the mix"), ("time", "until slushy"))
    vocab = vocabulary(RECIPE, [], blend)
    assert "mix" in vocab.objects and "slushy" in vocab.states
    grammar = to_gbnf(vocab, max_lines=12, comments=False)
    assert accepts(grammar, body_text(["put(mix, blender)", "turn_on(blender)", "wait(mix == slushy)"]))
    timed = vocabulary(RECIPE, [], action("simmer", ("what", "sauce"), ("time", "for 20 minutes")))
    assert timed.durations == ("20_minutes",)
    assert admits(timed, Call("wait", ("timer", "20_minutes"))) and admits(timed, Call("wait", ("timer", "2_hours")))
    assert not admits(timed, Call("wait", ("sauce", "20_minutes")))


def test_library_verbs_join_later_grammars_but_not_their_own():
    library = [("boil", ("what",)), ("bake", ("what", "time")), ("put", ("what",))]
    vocab = vocabulary(RECIPE, library, action("mash", ("what", "potatoes")))
    grammar = to_gbnf(vocab, max_lines=12, comments=False)
    assert accepts(grammar, body_text(["boil(potatoes)", "bake(potatoes, golden)", "stir(potatoes)"]))
    assert not accepts(grammar, body_text(["boil(potatoes, pot)"]))
    assert [s.name for s in vocab.shapes].count("put") == 1  # a library "put" never shadows the primitive
    own = vocabulary(RECIPE, library, action("boil", ("what", "rice")))
    assert not admits(own, Call("boil", ("rice",)))  # no recursion into the verb being reduced


def test_a_state_named_like_a_primitive_is_not_offered():
    vocab = vocabulary(THOR, [], action("drain", ("what", "pasta"), ("time", "until empty")))
    assert "empty" not in vocab.states  # empty(pasta) would read as the action empty


def test_a_temperature_is_a_state_not_a_duration():
    vocab = vocabulary(RECIPE, [], action("preheat", ("what", "the oven"), ("temperature", "350 degrees")))
    assert vocab.durations == () and "350_degrees" in vocab.states
    assert admits(vocab, Call("wait", ("oven", "350_degrees")))
    assert not admits(vocab, Call("wait", ("timer", "350_degrees")))


# Verbs an imported library could hold: a quote that once broke every later grammar, one that widened the
# grammar to any line, a line break, a rule of its own, controls.
HOSTILE_VERBS = ('bad"verb', 'x" | [^\n]* | "y', "two\nlines", 'ok ::= [^"]*', "esc\x1b[2J", "back\\slash", "Boil",
                 "boil me", "")


def test_hostile_library_verbs_leave_every_grammar_as_narrow_as_without_them():
    mash = action("mash", ("what", "potatoes"))
    plain = vocabulary(RECIPE, [("boil", ("what",))], mash)
    hostile = vocabulary(RECIPE, [("boil", ("what",)), *((verb, ("what",)) for verb in HOSTILE_VERBS),
                                  ("blend", ('what"', "where"))], mash)
    assert hostile == plain
    for avoid in ((), ("put",)):
        grammar = to_gbnf(hostile, max_lines=12, comments=True, avoid=avoid)
        assert grammar == to_gbnf(plain, max_lines=12, comments=True, avoid=avoid)
        assert accepts(grammar, body_text(["boil(potatoes)", "stir(potatoes)"]))  # valid, and as before
        for verb in HOSTILE_VERBS:
            assert not accepts(grammar, body_text([f"{verb}(potatoes)"])), verb
        assert not accepts(grammar, body_text(["anything at all"]))


def test_why_a_library_verb_is_not_offered():
    from cook2ltl.reduce.grammar import unusable_verb
    from cook2ltl.reduce.reduction import LibraryVerb, offered_verbs

    library = [LibraryVerb("boil", ("what",), "pick_up($what)"), LibraryVerb('bad"verb', ("what",), ""),
               LibraryVerb("blend", ("what", "x y"), "")]
    offered, reasons = offered_verbs(library)
    assert offered == library[:1]
    assert reasons == (unusable_verb('bad"verb', ("what",)), unusable_verb("blend", ("what", "x y")))
    assert "'bad\"verb' is not a lower-case identifier" in reasons[0] and "blend" in reasons[1]


def test_a_gbnf_literal_matches_exactly_its_text():
    from cook2ltl.reduce.grammar import gbnf_literal
    from cook2ltl.reduce.llm import line_grammar

    for text in ('say "hi"', "a\\b", "new\nline\r\t", "\x00\x1b[2J\x7f\x9b", "\u202e\u2028", "🍳", 'x" | [^\n]* | "y'):
        literal = gbnf_literal(text)
        assert "\n" not in literal and literal.isprintable(), literal
        assert accepts(f"root ::= {literal}", text)
        assert not accepts(f"root ::= {literal}", text + "x")
        grammar = line_grammar([text, "pick_up(pot)"])
        assert accepts(grammar, f"    {text}\n") and accepts(grammar, "    pick_up(pot)\n")
        assert not accepts(grammar, "    anything\n")
