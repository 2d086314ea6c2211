"""What the dependency parse adds around a verb that the span model got wrong: the particle of a phrasal
verb, and a direct object no span covers.

The span model learnt from recipes, where "on" mostly starts a place ("place on a plate"); switching an
appliance is rare there, so "switch on the toaster" comes out as switch(where: on the toaster) and "turn the
faucet on" as turn(faucet, where: on). The parse knows better: a particle (`prt`) belongs to its verb, and
"turn"/"switch" followed by on/off is switching, whatever the parse calls the word. An object the verb takes
directly (`dobj`) that no span covers ("heat up *the coffee*") is the action's What.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from cook2ltl.domain.recipe import Label, Span, Token

# Particles that change what a verb does (turn *on*, switch *off*, heat *up*); "stir in" or "pour over" keep
# their verb's meaning and name where things go, so they are not joined.
PARTICLES = {"on", "off", "up", "down"}
SWITCHING = ({"turn", "switch"}, {"on", "off"})  # verbs whose on/off is always the switch, never a place


def particle(verb: Span, tokens: Sequence[Token], arguments: Sequence[Span]) -> tuple[str, list[Span]]:
    """The particle of the verb's phrasal verb ("" if none) and the arguments without it: an argument that is
    only the particle is dropped; a place it starts ("on the toaster" after "switch") becomes the What."""
    heads = _verb_tokens(verb, tokens)
    if not heads or any(tokens[i].text.lower() in PARTICLES for i in heads):
        return "", list(arguments)
    switching = tokens[heads[0]].text.lower() in SWITCHING[0]
    for index, token in enumerate(tokens):
        word = token.text.lower()
        if word not in PARTICLES or token.head not in heads or index <= heads[-1]:
            continue
        inside = next((a for a in arguments if a.start <= token.start and token.end <= a.end), None)
        follows = index == heads[-1] + 1
        if inside is None and (token.dep == "prt" or (switching and follows and word in SWITCHING[1])):
            return word, list(arguments)
        if inside is not None and (token.dep == "prt" or switching and word in SWITCHING[1]):
            if inside.text.strip().lower() == word:
                return word, [a for a in arguments if a is not inside]
            if follows and inside.start == token.start:  # "switch on the toaster": the toaster is switched
                rest = _after(inside, token.end)
                return word, [rest if a is inside else a for a in arguments]
    return "", list(arguments)


def missed_objects(verbs: Sequence[Span], tokens: Sequence[Token], spans: Sequence[Span]) -> list[Span]:
    """What spans for objects the verbs take directly that no span covers, with their modifiers: a `dobj`, or
    the object of a particle inside the verb's span ("turn on | the stove")."""
    found = []
    for verb in verbs:
        heads = _verb_tokens(verb, tokens)
        for index, token in enumerate(tokens):
            direct = token.dep == "dobj" or (token.dep == "pobj" and heads[1:] and token.head in heads[1:])
            if token.head in heads and direct and index not in heads:
                first, last = _subtree(index, tokens)
                start, end = tokens[first].start, tokens[last].end
                if not any(s.start < end and start < s.end for s in spans):
                    found.append(Span(Label.WHAT, start, end, _text(tokens[first:last + 1]), score=0.0))
    return found


def _text(tokens: Sequence[Token]) -> str:
    """The words as written, one space wherever the text had a gap."""
    return "".join((" " if i and t.start > tokens[i - 1].end else "") + t.text for i, t in enumerate(tokens))


def _verb_tokens(verb: Span, tokens: Sequence[Token]) -> list[int]:
    return [i for i, t in enumerate(tokens) if verb.start <= t.start and t.end <= verb.end]


def _subtree(index: int, tokens: Sequence[Token]) -> tuple[int, int]:
    """The first and last token of the phrase headed by `index` (its words, however deep)."""
    inside = {index}
    grown = True
    while grown:
        more = {i for i, t in enumerate(tokens) if t.head in inside and i != t.head} - inside
        grown = bool(more)
        inside |= more
    return min(inside), max(inside)


def _after(span: Span, cut: int) -> Span:
    text = span.text[cut - span.start:]
    lead = len(text) - len(text.lstrip())
    return replace(span, label=Label.WHAT, start=cut + lead, text=text.strip())
