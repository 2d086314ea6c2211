"""One library entry in full: its body, its provenance and review, the kitchen check, the intended effect, and
every version."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.content import Content
from textual.widgets import Static

from cook2ltl.reduce.validation import CheckStatus
from cook2ltl.ui.literal import shown

if TYPE_CHECKING:
    from cook2ltl.library import LibraryEntry, Version
    from cook2ltl.library.versions import Review

STATUS_STYLE = {"pending": "$text-warning", "approved": "$text-success", "rejected": "$text-error"}
CHECK_STYLE = {CheckStatus.PASSED: "$text-success", CheckStatus.FAILED: "$text-error",
               CheckStatus.UNCHECKED: "$text-muted"}
EMPTY = "No entry: the library grows as translations reduce actions with the model."


def status_content(status: str) -> Content:
    return shown(status).stylize(STATUS_STYLE.get(status, "$text-muted"))


def check_content(validation: str) -> Content:
    return shown(validation).stylize(CHECK_STYLE.get(validation, "$text-muted"))


class EntryDetail(Static):
    """Blank until an entry is chosen; the versions arrive a moment later, read by a worker."""

    def show(self, entry: LibraryEntry | None, versions: tuple[Version, ...] = (),
             reviews: tuple[Review, ...] = ()) -> None:
        if entry is None:
            self.update(EMPTY)
            return
        parts = [_body(entry), _review(entry)]
        if versions:
            parts.append(_history(versions, reviews))
        self.update(Content("\n\n").join(parts))


def _body(entry: LibraryEntry) -> Content:
    from cook2ltl.library.store import shown_body  # startup: the app opens before the library (sqlite-utils) loads

    title = shown(entry.action).stylize("bold") + shown(f"  #{entry.id} · version {entry.version} · "
                                                        f"{entry.primitives} primitives").stylize("$text-muted")
    return title + Content("\n") + shown(shown_body(entry.body)).stylize("$text-accent")


def _review(entry: LibraryEntry) -> Content:
    from cook2ltl.library.effect import shown_effect  # startup: the app opens before the library (sqlite-utils) loads

    reviewed = f"  by {entry.reviewed_by} at {entry.reviewed_at}" if entry.reviewed_by else ""
    lines = [
        _label("status") + status_content(entry.status.value) + shown(reviewed).stylize("$text-muted"),
        _label("kitchen") + check_content(entry.validation),
        *(shown(f"{'':<11}✗ {problem}").stylize("$text-error") for problem in entry.problems),
        _label("effect") + shown(shown_effect(entry.effect)),
        _label("learnt by") + shown(f"{entry.model} · prompt {entry.prompt_hash[:12] or '—'} · {entry.created}"),
    ]
    if entry.example:
        example = ", ".join(f"{placeholder} = {value}" for placeholder, value in entry.example)
        lines.append(_label("learnt for") + shown(example))
    return Content("\n").join(lines)


def _history(versions: tuple[Version, ...], reviews: tuple[Review, ...]) -> Content:
    from cook2ltl.library.store import shown_body  # startup: the app opens before the library (sqlite-utils) loads

    lines = [Content("history").stylize("bold")]
    for version in reversed(versions):  # newest first
        note = f" · {version.note}" if version.note else ""
        lines += [Content("    ") + status_content(review.status) + shown(f" by {review.reviewer} at {review.at}")
                  for review in reversed(reviews) if review.version == version.version]
        lines.append(Content(f"v{version.version:<3}").stylize("bold") + shown(f"{version.at} {version.author}")
                     + shown(note).stylize("$text-muted") + Content("  ") + check_content(version.validation))
        if version is not versions[-1]:
            lines.append(shown("    " + shown_body(version.body).replace("\n", " · ")).stylize("$text-muted"))
    return Content("\n").join(lines)


def _label(text: str) -> Content:
    return Content(f"{text:<11}").stylize("$text-muted")
