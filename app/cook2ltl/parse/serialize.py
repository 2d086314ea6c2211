"""Parsed recipes as plain JSON-ready dicts: every span with its label and offsets into the input."""

from __future__ import annotations

from cook2ltl.domain.recipe import ARGUMENT_LABELS, Argument, Frame, ParsedRecipe, Span, field_of


def span_json(span: Span) -> dict:
    return {"label": span.label.value, "start": span.start, "end": span.end, "text": span.text, "score": span.score}


def argument_json(argument: Argument) -> dict:
    return {**span_json(argument.span), "inferred": argument.inferred}


def frame_json(frame: Frame) -> dict:
    return {
        "signature": frame.signature(),
        "verb": span_json(frame.verb),
        **{field_of(label): [argument_json(a) for a in frame.arguments(label)] for label in ARGUMENT_LABELS},
        "negated": frame.negated,
        "objects_joined_by": frame.objects_joined_by.value,
    }


def recipe_json(recipe: ParsedRecipe) -> dict:
    return {
        "steps": [
            {
                "index": step.index,
                "text": step.sentence.text,
                "start": step.sentence.start,
                "end": step.sentence.end,
                "spans": [span_json(span) for span in step.spans],
                "frames": [frame_json(frame) for frame in step.frames],
                "links": [link.value for link in step.links],
            }
            for step in recipe.steps
        ],
    }
