"""`cook2ltl translate`: per step the frames, their reductions (primitive, library or new) and the formula."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer
from rich.console import Console

from cook2ltl import paths
from cook2ltl.assembly.backends import DEFAULT_MODEL
from cook2ltl.errors import UserError
from cook2ltl.pipeline.records import Translation, Variant
from cook2ltl.preprocess.recipe_file import read_recipe
from cook2ltl.text_safety import json_text, terminal
from cook2ltl.world.export import export_pddl


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
    exact_keys: bool = typer.Option(False, "--exact-keys",
                                    help="Reuse a library entry only for its own verb and signature, not for a verb "
                                         "the verb-effect table reads as the same action or another signature."),
    as_json: bool = typer.Option(False, "--json", help="Print machine-readable JSON."),
    pddl: Optional[Path] = typer.Option(None, "--pddl", help="Also write the world model's domain, the problem "
                                        "and the plan as PDDL into this folder."),
) -> None:
    """Translate a recipe into LTL formulas over the robot's primitive actions (the paper's Algorithm 1)."""
    # startup: `cook2ltl --help` imports this module; the pipeline loads when the command runs
    from cook2ltl.assembly.translators import TranslateOptions
    from cook2ltl.cli.translating import open_translator, translated
    from cook2ltl.pipeline.report import show
    from cook2ltl.pipeline.serialize import translation_json
    from cook2ltl.reduce.primitives import load_primitives
    from cook2ltl.reduce.reduction import ReductionSettings

    library = paths.user_path(library, "--library") if library else None
    pddl = paths.output_folder(pddl, "--pddl") if pddl else None  # made now: a bad folder fails before the run
    text = read_recipe(recipe)
    errors = terminal(stderr=True)
    options = TranslateOptions(variant, ReductionSettings(max_lines, comments), validate, repairs, approved_only,
                               ground, reuse=not exact_keys)
    with open_translator(load_primitives(primitives), model, library, options, errors) as translator:
        translation = translated(text, translator, errors)
    if pddl is not None:
        _export(translation, translator.grounding, pddl, errors)
    if as_json:
        typer.echo(json_text(translation_json(translation)))
    else:
        show(translation, terminal())


def _export(translation: Translation, grounding, folder: Path, errors: Console) -> None:
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
