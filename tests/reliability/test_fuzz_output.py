"""Fuzzing targets: text a user, a file, a library or a model could hold, printed and spliced.

Printed through cook2ltl.text_safety (the CLI's consoles) or ui.literal (the app), it never raises and never
reaches the terminal as a control sequence; spliced into a GBNF grammar as a library verb or an object, the
grammar stays valid and no wider than without it.
"""

from __future__ import annotations

import io
import json
import re

from hypothesis import given
from hypothesis import strategies as st
from rich.table import Table
from rich.text import Text

from cook2ltl.domain.actions import Action, Parameter
from cook2ltl.reduce.grammar import to_gbnf, vocabulary
from cook2ltl.reduce.llm import line_grammar
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.text_safety import json_text, literal, styled, terminal, visible
from cook2ltl.ui.literal import shown
from tests.reduce.gbnf import accepts, gbnf_regex
from tests.reliability.hostile import FUZZ, TRIED

PIECES = ("[", "]", "[/]", "[/nope]", "[bold red]", "[link=https://example.org]", "[@click=app.quit]", "[$accent]",
          ":smile:", "\\", "\\[", '"', "'", "\x1b[2J", "\x1b[31m", "\x1b]0;title\x07", "\x1b]8;;https://x\x1b\\",
          "\x1bP+q\x1b\\", "\x9b31m", "\x9d0;t\x9c", "\x00", "\x07", "\x08", "\r", "\x0b", "\x7f", "\x85", "\u202e",
          "\u2066", "\u200f", "\u061c", "\ud800", "\n", "\t", " ", "|", "::=", "x", "é", "🍳")
hostile = st.one_of(
    st.lists(st.one_of(st.sampled_from(PIECES), st.characters(codec="utf-8")), max_size=24).map("".join),
    st.text(max_size=60),
)
# What a terminal would obey: C0 controls but newline and tab, DEL, C1 controls, bidi controls; and lone
# surrogates, which no terminal encoding has.
OBEYED = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069\ud800-\udfff]")
RECIPE = load_primitives("recipe")
NAME = re.compile(r"[a-z][a-z0-9_]*\Z")
ARGUMENT = re.compile(r"[a-z0-9][a-z0-9_]*\Z")


def printed(*renderables, **options) -> str:
    file = io.StringIO()
    console = terminal(file=file, width=100)
    for renderable in renderables:
        console.print(renderable, **options)
    return file.getvalue()


@FUZZ
@given(hostile)
def test_printed_text_is_shown_literally(text):
    TRIED["terminal output"] += 1
    table = Table("a", text, title=text)
    table.add_row(text, literal(text, "bold"))
    out = printed(text, literal(text), styled(("x", "bold"), text, (text, "red")), table, Text(text), f"[b]{text}")
    assert not OBEYED.search(out), repr(out)
    out.encode("utf-8")  # a terminal can be sent every character
    if "\t" not in text:  # (rich lays tabs out as spaces)
        assert printed(literal(text), soft_wrap=True) == visible(text) + "\n"


@FUZZ
@given(hostile)
def test_json_and_the_app_show_text_literally(text):
    TRIED["terminal output"] += 1
    out = json_text({"field": text})
    assert not OBEYED.search(out) and json.loads(out) == {"field": text}
    content = shown(text)
    assert content.plain == visible(text) and not OBEYED.search(content.plain)


@FUZZ
@given(st.lists(hostile, min_size=1, max_size=4), hostile)
def test_hostile_verbs_and_objects_leave_the_grammar_valid_and_narrow(words, thing):
    TRIED["grammar splicing"] += 1
    stir = Action("stir", (Parameter("what", "the soup", "soup", "soup"),))
    hostile_stir = Action("stir", (*stir.parameters, Parameter("what", thing, thing, thing),
                                   Parameter("time", thing, thing, thing)))
    plain = to_gbnf(vocabulary(RECIPE, [("boil", ("what",))], stir), 12, comments=True)
    library = [("boil", ("what",)), *((word, ("what",)) for word in words), ("blend", (thing,))]
    grammar = to_gbnf(vocabulary(RECIPE, library, hostile_stir), 12, comments=True)
    gbnf_regex(grammar)  # valid: every rule reads
    if not any(NAME.match(word) for word in words) and not NAME.match(thing) and not ARGUMENT.match(thing):
        assert grammar == plain  # not one more line admitted
    for word in (*words, thing):
        if not ARGUMENT.match(word):
            assert not accepts(grammar, f"    {word}(soup)\n\n") and not accepts(grammar, f"    put({word}, pot)\n\n")


@FUZZ
@given(st.lists(hostile, min_size=1, max_size=4))
def test_a_line_grammar_admits_its_options_and_nothing_else(options):
    TRIED["grammar splicing"] += 1
    grammar = line_grammar(options)
    for option in options:
        assert accepts(grammar, f"    {option}\n")
    assert accepts(grammar, "\n")
    stranger = "".join(options) + "\x1b"
    assert not accepts(grammar, f"    {stranger}\n")
