"""A translation as plain JSON-ready dicts: per step its frames, reductions and formula; stats at the top."""

from __future__ import annotations

from dataclasses import asdict

from cook2ltl.ltl.printer import to_spot, to_unicode
from cook2ltl.parse.serialize import frame_json
from cook2ltl.pipeline import ActionResult, StepResult, Translation


def translation_json(translation: Translation) -> dict:
    return {
        "primitives": translation.primitives,
        "variant": translation.variant.value,
        "model": translation.model,
        "formula": to_spot(translation.formula),
        "formula_unicode": to_unicode(translation.formula),
        "steps": [step_json(step) for step in translation.steps],
        "stats": asdict(translation.stats),
    }


def step_json(step: StepResult) -> dict:
    return {
        "index": step.step.index,
        "text": step.step.sentence.text,
        "frames": [frame_json(frame) for frame in step.step.frames],
        "links": [link.value for link in step.step.links],
        "actions": [action_json(result) for result in step.actions],
        "formula": to_spot(step.formula),
        "formula_unicode": to_unicode(step.formula),
        "problems": list(step.problems),
    }


def action_json(result: ActionResult) -> dict:
    reduction = result.reduction
    return {
        "frame": result.frame_index,
        "action": reduction.action.text(),
        "verb": reduction.action.verb,
        "signature": list(reduction.action.signature),
        "source": reduction.source.value,
        "body": [call.text() for call in reduction.body],
        "plan": [call.text() for call in result.plan],
        "dropped": list(reduction.dropped),
        "library_entry": reduction.entry_id,
        "usage": asdict(reduction.usage),
        "check": result.check.json() if result.check is not None else None,
    }
