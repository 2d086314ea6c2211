"""A translation as plain JSON-ready dicts, as `translate --json` prints it and the app writes it: per step its
frames, reductions (with their kitchen checks and repairs) and formula; the stats and the two rates at the top."""

from __future__ import annotations

from dataclasses import asdict

from cook2ltl.ltl.printer import to_spot, to_unicode
from cook2ltl.parse.serialize import frame_json
from cook2ltl.pipeline.rates import rates
from cook2ltl.pipeline.records import ActionResult, StepResult, Translation


def translation_json(translation: Translation) -> dict:
    return _with_validation({
        "primitives": translation.primitives,
        "variant": translation.variant.value,
        "model": translation.model,
        "formula": to_spot(translation.formula),
        "formula_unicode": to_unicode(translation.formula),
        "steps": [step_json(step) for step in translation.steps],
        "stats": asdict(translation.stats),
    }, translation)


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
        # a library entry learnt for another verb or signature: which one, and why it serves (library.reuse)
        "reused": result.reuse.json() if result.reuse is not None else None,
    }


def _with_validation(data: dict, translation: Translation) -> dict:
    """The translation's JSON with each new reduction's kitchen check and the two rates in the stats."""
    results = [result for step in translation.steps for result in step.actions]
    actions = [action for step in data["steps"] for action in step["actions"]]
    for action, result in zip(actions, results):
        check = result.validation
        action["validation"] = None if check is None else {
            "status": check.status, "problems": list(check.messages()), "scene": check.scene,
            "seconds": round(check.seconds, 4)}
        action["repairs"] = [[call.text() for call in attempt.body] for attempt in result.attempts]
        if result.entry_validation is not None:
            action["library_validation"] = {"status": result.entry_validation, "problems": list(result.entry_problems)}
    counts = rates(translation)
    data["skipped_verbs"] = list(translation.skipped_verbs)
    data["stats"] |= {"executability": counts.executability, "validated_rate": counts.validated_rate,
                      "written_lines": counts.written_lines, "admissible_lines": counts.admissible_lines}
    return data
