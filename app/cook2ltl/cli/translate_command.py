"""`cook2ltl translate`: per step the frames, their reductions (primitive, library or new) and the formula."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer
from rich.console import Console

from cook2ltl import paths
from cook2ltl.cli.inputs import read_recipe
from cook2ltl.pipeline import Translation, Variant
from cook2ltl.translate.rates import rates
from cook2ltl.reduce.llm import DEFAULT_MODEL
from cook2ltl.reduce.model import Source
from cook2ltl.text_safety import json_text, literal, styled, terminal

SOURCE_STYLE = {Source.PRIMITIVE: "green", Source.LIBRARY: "cyan", Source.LLM: "magenta", Source.WORLD: "dim"}


def translate_command(
    recipe: str = typer.Argument(..., help="Recipe text file, or - for standard input."),
    primitives: str = typer.Option("recipe", "--primitives", help="recipe, ai2thor, or a TOML file of your robot's set."),
    variant: Variant = typer.Option(Variant.AR_LIBRARY, "--variant", case_sensitive=False,
                                    help="AR* reduces every action; AR passes primitives through; "
                                         "AR+A also reuses and grows the action library."),
    library: Optional[Path] = typer.Option(None, "--library", help="Action library file (default: $COOK2LTL_LIBRARY, "
                                           "else library.sqlite in the user data folder)."),
    model: str = typer.Option(DEFAULT_MODEL, "--model", help="Language model of the manifest (`cook2ltl models`)."),
    max_lines: int = typer.Option(12, "--max-lines", min=1, max=40, help="Most lines one reduction may have."),
    comments: bool = typer.Option(False, "--comments/--no-comments",
                                  help="Let the model comment each line, as the paper's prompt does (about 2x slower)."),
    validate: Optional[bool] = typer.Option(None, "--validate/--no-validate",
                                            help="Run each new reduction in the THOR kitchen before caching it "
                                                 "(default: on for AR+A)."),
    repairs: Optional[int] = typer.Option(None, "--repairs", min=0, max=10, show_default=False,
                                          help="How many times a plan that fails in the kitchen goes back to the "
                                               "model (default: the settings' [translate] repairs, else 2)."),
    ground: bool = typer.Option(True, "--ground/--no-ground",
                                help="Check every plan in the primitive set's world model where the recipe has got to, "
                                     "and let the planner complete it to the action's intended effect."),
    approved_only: bool = typer.Option(False, "--approved-only",
                                       help="Reuse only approved library entries (new ones are still cached, pending)."),
    as_json: bool = typer.Option(False, "--json", help="Print machine-readable JSON."),
    pddl: Optional[Path] = typer.Option(None, "--pddl", help="Also write the world model's domain, the problem "
                                        "and the plan as PDDL into this folder."),
) -> None:
    """Translate a recipe into LTL formulas over the robot's primitive actions (the paper's Algorithm 1)."""
    from cook2ltl.cli.translating import open_translator, translated
    from cook2ltl.reduce.primitives import load_primitives
    from cook2ltl.reduce.reduction import ReductionSettings
    from cook2ltl.translate.serialize import translation_json

    library = paths.user_path(library, "--library") if library else None
    pddl = paths.output_folder(pddl, "--pddl") if pddl else None  # made now: a bad folder fails before the run
    text = read_recipe(recipe)
    errors = terminal(stderr=True)
    with open_translator(load_primitives(primitives), model, library, variant, ReductionSettings(max_lines, comments),
                         validate, repairs, approved_only, ground, errors) as translator:
        translation = translated(text, translator, errors)
    if pddl is not None:
        _export(translation, translator.grounding, pddl, errors)
    if as_json:
        typer.echo(json_text(with_validation(translation_json(translation), translation)))
    else:
        show(translation, terminal())


def _export(translation: Translation, grounding, folder: Path, errors: Console) -> None:
    from cook2ltl.errors import UserError
    from cook2ltl.world.export import export_pddl

    if grounding is None or translation.world_start is None:
        raise UserError("--pddl needs the world model.", "drop --no-ground, or use a primitive set with a [world].")
    results = [r for step in translation.steps for r in step.actions]
    plan = [call for r in results for call in r.plan]
    effects = [fact for r in results if r.check is not None for fact in r.check.effect]
    try:
        written = export_pddl(grounding.world, translation.world_start, plan, effects, folder)
    except OSError as error:  # the folder was made before the run; a full disk, or a file put in the way since
        raise UserError(f"Cannot write the PDDL files into {paths.shown(folder)}: {error.strerror or error}.",
                        "give --pddl a folder you may write to.") from None
    for path in written:
        errors.print(f"wrote {path}")


def with_validation(data: dict, translation: Translation) -> dict:
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


def show(translation: Translation, console: Console) -> None:
    from cook2ltl.ltl.printer import to_spot, to_unicode

    console.print(literal(f"primitives {translation.primitives} · variant {translation.variant.value} · "
                          f"model {translation.model}", "dim"))
    for reason in translation.skipped_verbs:
        console.print(literal(f"! {reason}", "yellow"), highlight=False)
    for step in translation.steps:
        console.print(styled((f"{step.step.index + 1:>3}. ", "dim"), step.step.sentence.text))
        for index, frame in enumerate(step.step.frames):
            console.print(literal("      " + frame.signature(), "dim"))
            for result in (r for r in step.actions if r.frame_index == index):
                _show_reduction(result, console)
        console.print(styled(("      φ = ", "dim"), (to_unicode(step.formula), "yellow")), soft_wrap=True)
        console.print(literal("          " + to_spot(step.formula), "dim"), soft_wrap=True)
        for problem in step.problems:
            console.print(styled("      ", ("!", "bold red"), " ", problem), highlight=False)
    stats = translation.stats
    console.print(literal(
        f"{stats.actions} actions: {stats.primitive} primitive, {stats.library_hits} from the library, "
        f"{stats.llm_calls} LLM calls ({stats.prompt_tokens} prompt + {stats.completion_tokens} completion tokens, "
        f"{stats.llm_seconds:.1f} s); {stats.new_entries} new library entries; {stats.seconds:.1f} s in all", "dim"))
    console.print(literal(rates_line(translation), "dim"), highlight=False, soft_wrap=True)


def rates_line(translation: Translation) -> str:
    counts, stats = rates(translation), translation.stats
    line = "executability " + (f"{counts.executability:.0%} ({counts.admissible_lines} of {counts.written_lines} "
                               f"lines the model wrote are admissible)" if counts.executability is not None else "-")
    if counts.validated_rate is None:
        return line + "; validated -" + ("" if translation.validating else " (not validating)")
    return (line + f"; validated {counts.validated_rate:.0%} ({stats.validated} of {counts.new_reductions} new "
            f"reductions run in the kitchen, {stats.repaired} after repair; {stats.repair_calls} repair calls; "
            f"{stats.checked} checked)")


def _show_reduction(result, console: Console) -> None:
    reduction = result.reduction
    entry = f" #{reduction.entry_id}" if reduction.entry_id is not None else ""
    console.print(styled("        → ", (reduction.action.text(), "bold"),
                         (f"  {reduction.source.value}{entry}", SOURCE_STYLE[reduction.source])))
    if reduction.source != Source.PRIMITIVE:
        for call in reduction.body:
            console.print(literal(f"            {call.text()}"), highlight=False)
    for dropped in reduction.dropped:
        console.print(styled("            ", (f"✗ {dropped}", "red"), " ", ("(not admissible, dropped)", "dim")),
                      highlight=False)
    check = result.validation
    if check is not None:
        repaired = f", after {len(result.attempts)} repair{'s' if len(result.attempts) > 1 else ''}" if result.attempts else ""
        style = "green" if check.passed else "yellow" if not check.checked else "red"
        console.print(styled("            ", (f"kitchen check: {check.status}", style), " ",
                             (f"({check.scene or 'no scene'}{repaired})", "dim")), highlight=False)
        for message in check.messages():
            console.print(literal(f"            ! {message}", style), highlight=False)
    if result.entry_validation == "failed":
        console.print(literal("            kitchen check when learnt: failed", "red"), highlight=False)
        for message in result.entry_problems:
            console.print(literal(f"            ! {message}", "red"), highlight=False)
