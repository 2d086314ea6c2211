"""Text from a user, a file, a library, a recipe or a model, shown literally on a terminal.

Two things in such text could act instead of being read: rich or Textual markup (`[/nope]` raises, `[link=…]`
hides), and characters a terminal obeys (ESC starting a CSI or OSC sequence, the other C0 and C1 controls,
bidi overrides that reorder what is shown). Markup is never parsed here: the CLI's consoles have markup off
and text goes into rich `Text` (Textual `Content`) objects, which are not markup. Controls are written out
as escapes (ESC as `\\x1b`), so a reader sees them and the terminal never receives them.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable

from rich.console import Console, ConsoleOptions, RenderableType
from rich.segment import Segment
from rich.text import Span, Text

# C0 controls but tab and newline, DEL and the C1 controls, lone surrogates (no terminal encoding has them),
# and the bidi controls (U+061C, U+200E/F, U+202A–E, U+2066–9) that make a terminal reorder what follows.
_HIDDEN = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\ud800-\udfff\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]")


def visible(text: str) -> str:
    """The text with every control character written out as an escape: "a\\x1b[2Jb" shows as a\\x1b[2Jb."""
    return _HIDDEN.sub(_escape, text)


def _escape(match: re.Match) -> str:
    code = ord(match.group())
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def literal(text: object, style: str = "") -> Text:
    """A rich Text showing `text` exactly, controls made visible; markup in it is only characters. A Text
    keeps its styles, moved along with the characters they cover."""
    if isinstance(text, Text):
        return _visible_text(text, style)
    return Text(visible(str(text)), style=style)


def _visible_text(text: Text, style: str) -> Text:
    if not style and not _HIDDEN.search(text.plain):
        return text
    shown = [visible(char) for char in text.plain]
    offsets = [0]
    for piece in shown:
        offsets.append(offsets[-1] + len(piece))
    spans = [Span(offsets[span.start], offsets[span.end], span.style) for span in text.spans]
    return Text("".join(shown), style=style or text.style, justify=text.justify, overflow=text.overflow,
                no_wrap=text.no_wrap, end=text.end, spans=spans)


def styled(*parts: str | tuple[str, str] | Text) -> Text:
    """`Text.assemble` with every string shown literally: styled("entry ", (name, "bold"), " approved")."""
    return Text.assemble(*(_part(part) for part in parts))


def _part(part: str | tuple[str, str] | Text) -> str | tuple[str, str] | Text:
    if isinstance(part, str):
        return visible(part)
    if isinstance(part, tuple):
        return visible(part[0]), part[1]
    return literal(part)


def json_text(data: object) -> str:
    """Indented JSON a terminal can show: controls, bidi characters and lone surrogates as \\u escapes, which
    JSON reads back as the same characters (they can only occur inside strings)."""
    return _HIDDEN.sub(lambda m: f"\\u{ord(m.group()):04x}", json.dumps(data, ensure_ascii=False, indent=2))


class LiteralConsole(Console):
    """A rich Console that never parses markup or emoji codes in strings and shows their controls as escapes.

    Text objects should come from `literal`, so that they are measured as shown; any that did not are still
    made visible as they are rendered (a table cell may then be cut short), so a print site that forgot
    cannot send a control sequence to the terminal. The style codes rich writes itself are not text."""

    def __init__(self, **options) -> None:
        super().__init__(**{"markup": False, "emoji": False, **options})

    def render_str(self, text: str, **options) -> Text:
        return super().render_str(visible(text), **options)

    def render(self, renderable: RenderableType, options: ConsoleOptions | None = None) -> Iterable[Segment]:
        if isinstance(renderable, Text):  # laid out as shown
            renderable = literal(renderable)
        for segment in super().render(renderable, options):
            if segment.control or not _HIDDEN.search(segment.text):
                yield segment
            else:
                yield Segment(visible(segment.text), segment.style)


def terminal(stderr: bool = False, **options) -> LiteralConsole:
    """The console every command prints through: standard output, or standard error for progress and errors."""
    return LiteralConsole(stderr=stderr, **options)
