"""Characters a reader cannot see, made plain spaces before anything reads the recipe.

Zero-width joiners, bidirectional overrides, byte-order marks, control characters and lone surrogates
carry no instruction, yet they split words ("sa\u200blt"), reorder what a terminal shows (U+202E) or break
encoders further on. Each becomes one space, so every offset into the cleaned text is an offset into the
text as given.
"""

from __future__ import annotations

import unicodedata

KEPT_CONTROLS = "\n\r\t"
HIDDEN_CATEGORIES = {"Cc", "Cf", "Cs"}  # controls, format characters, surrogates


def visible_text(text: str) -> str:
    if text.isascii() and text.isprintable():
        return text  # the common case, a plain one-line recipe
    return "".join(" " if _hidden(ch) else ch for ch in text)


def _hidden(ch: str) -> bool:
    return ch not in KEPT_CONTROLS and unicodedata.category(ch) in HIDDEN_CATEGORIES
