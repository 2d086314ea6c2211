"""Text from a recipe, a library, a file or a model as the app shows it: literally.

Textual reads markup in the strings given to Static, Label, DataTable cells and notifications, and sends
control characters in any text to the terminal as they are. `shown` gives Content, which is never read as
markup, with the controls written out as escapes (cook2ltl.text_safety).
"""

from __future__ import annotations

from collections.abc import Iterable
from itertools import accumulate

from textual.content import Content

from cook2ltl.text_safety import visible


def shown(text: object) -> Content:
    """`text` as Content the app shows exactly: "[b]x\\x1b" appears as [b]x\\x1b, in no style."""
    return Content(visible(str(text)))


def shown_styled(text: str, styles: Iterable[tuple[int, int, str]]) -> Content:
    """`text` shown literally with (start, end, style) ranges of it styled; a range keeps covering its
    characters when a control before it is written out longer."""
    pieces = [visible(char) for char in text]
    offsets = list(accumulate((len(piece) for piece in pieces), initial=0))
    content = Content("".join(pieces))
    for start, end, style in styles:
        content = content.stylize(style, offsets[start], offsets[end])
    return content


def formula_text(formula, spot: bool = False) -> str | None:
    """The formula written in Unicode (or Spot) syntax; None when it is too large to write out."""
    # startup: the app opens before the LTL printer (lark) loads
    from cook2ltl.ltl.limits import FormulaTooLarge
    from cook2ltl.ltl.printer import to_spot, to_unicode

    try:
        return (to_spot if spot else to_unicode)(formula)
    except FormulaTooLarge:
        return None


def shown_formula(formula, spot: bool = False) -> Content:
    """The formula shown literally, or a note that it is too large to show (the app never fails drawing it)."""
    text = formula_text(formula, spot)
    return shown(text) if text is not None else Content("(too large to show)").stylize("$text-muted")
