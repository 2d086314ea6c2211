"""Read the paper's brat standoff annotations, repairing or skipping offsets that drifted from the text."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from cook2ltl.domain.recipe import Label, Span

# How far a drifted annotation may have moved and still be re-anchored to its surface text.
REANCHOR_WINDOW = 40
_LINE = re.compile(r"^T\d+\t(\w+) (\d+) (\d+)\t(.*)$")


@dataclass(frozen=True)
class AnnotatedRecipe:
    name: str
    text: str
    spans: tuple[Span, ...]
    repaired: int  # annotations whose offsets were wrong but whose text was found nearby
    skipped: tuple[str, ...]  # annotation lines that could not be matched, with the reason


def read_recipe(txt_path: Path) -> AnnotatedRecipe:
    text = txt_path.read_text(encoding="utf-8")
    spans: list[Span] = []
    skipped: list[str] = []
    repaired = 0
    for line in txt_path.with_suffix(".ann").read_text(encoding="utf-8").splitlines():
        match = _LINE.match(line)
        if not match:
            if line.strip():
                skipped.append(f"unreadable line: {line!r}")
            continue
        label, start, end, surface = match.groups()
        if label not in Label.__members__:
            skipped.append(f"unknown label {label}: {line!r}")
            continue
        start, end = int(start), int(end)
        anchored = _anchor(text, start, end, surface)
        if anchored is None:
            skipped.append(f"offsets {start}-{end} do not match {surface!r}")
            continue
        repaired += anchored != start
        spans.append(Span(Label(label), anchored, anchored + len(surface), surface))
    return AnnotatedRecipe(txt_path.stem, text, tuple(sorted(spans, key=_order)), repaired, tuple(skipped))


def read_corpus(folder: Path) -> list[AnnotatedRecipe]:
    """Every recipe<n>.txt with its .ann, in numeric order."""
    paths = sorted(folder.glob("recipe*.txt"), key=lambda p: int(re.sub(r"\D", "", p.stem) or 0))
    return [read_recipe(path) for path in paths if path.with_suffix(".ann").exists()]


def _anchor(text: str, start: int, end: int, surface: str) -> int | None:
    """The start at which `surface` really is: as given, or the nearest match within the window."""
    if text[start:end] == surface:
        return start
    low, high = max(0, start - REANCHOR_WINDOW), min(len(text), end + REANCHOR_WINDOW)
    found = [m.start() for m in re.finditer(re.escape(surface), text[low:high])]
    if not found:
        return None
    return low + min(found, key=lambda offset: abs(low + offset - start))


def _order(span: Span) -> tuple[int, int]:
    return span.start, -span.end
