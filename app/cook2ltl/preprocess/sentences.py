"""Sentence segmentation that survives cooking abbreviations.

A period ends a sentence unless it belongs to a number ("1.5"), a word that never ends one ("approx.",
"e.g."), or a unit ("min.", "tsp.", "350 F.") followed by something that does not start a sentence.
Line breaks always end a step; list markers ("1.", "2)", "-") are not part of it.
"""

from __future__ import annotations

import re

from cook2ltl.domain.recipe import Sentence

# Abbreviations that are never the last word of a sentence.
NEVER_FINAL = {
    "approx", "appr", "approximately", "e.g", "i.e", "eg", "ie", "vs", "ca", "mr", "mrs", "dr",
    "st", "no", "nos", "fig", "abt", "incl", "esp", "ea", "opt",
}
# Units: they may end a sentence ("Bake for 20 min. Serve."), but not when lower case follows.
UNITS = {
    "min", "mins", "hr", "hrs", "h", "sec", "secs", "tsp", "tsps", "tbsp", "tbsps", "tbs", "tbl", "oz", "lb",
    "lbs", "c", "pt", "pts", "qt", "qts", "gal", "pkg", "pkgs", "f", "deg", "in", "cm", "mm", "g", "kg", "ml",
    "l", "doz", "sq", "med", "lg", "sm", "env", "btl", "cont", "t",
}

_TERMINATOR = re.compile(r"[.!?]+[\"')\]]*")
_LIST_MARKER = re.compile(r"^\s*(?:(?:step\s*)?\d{1,3}\s*[.):]|[-*•·]|[a-z]\))\s+", re.IGNORECASE)
_WORD_BEFORE = re.compile(r"([A-Za-z][A-Za-z.]*)$")


def split_sentences(text: str) -> list[Sentence]:
    """Split `text` into sentences whose offsets point into `text` unchanged."""
    sentences: list[Sentence] = []
    for line_start, line in _lines(text):
        body_start = line_start + _marker_length(line)
        cut = body_start
        for match in _TERMINATOR.finditer(text, body_start, line_start + len(line)):
            if _ends_sentence(text, match.start(), match.end(), line_start + len(line)):
                _append(sentences, text, cut, match.end())
                cut = match.end()
        _append(sentences, text, cut, line_start + len(line))
    return sentences


def _lines(text: str):
    offset = 0
    for line in text.splitlines(keepends=True):
        yield offset, line.rstrip("\r\n")
        offset += len(line)


def _marker_length(line: str) -> int:
    match = _LIST_MARKER.match(line)
    return match.end() if match else 0


def _ends_sentence(text: str, start: int, end: int, line_end: int) -> bool:
    following = text[end:line_end]
    if following and not following[0].isspace():
        return False  # "1.5", "e.g.this", "3.)"
    if text[start] in "!?":
        return True
    word = _WORD_BEFORE.search(text[max(0, start - 24):start])
    token = word.group(1).lower().rstrip(".") if word else ""
    if token in NEVER_FINAL:
        return False
    next_char = following.lstrip()[:1]
    if token in UNITS or (len(token) == 1 and token.isalpha()):
        return next_char.isupper() or next_char == ""
    # A number before the period that a lower-case word continues: "at 350. then" is one sentence.
    return not next_char.islower()


def _append(sentences: list[Sentence], text: str, start: int, end: int) -> None:
    while start < end and text[start].isspace():
        start += 1
    while end > start and text[end - 1].isspace():
        end -= 1
    if end > start and any(ch.isalnum() for ch in text[start:end]):
        sentences.append(Sentence(text=text[start:end], start=start, end=end))
