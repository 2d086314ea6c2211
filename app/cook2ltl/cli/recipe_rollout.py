"""`cook2ltl rollout RECIPE-FILE`: the recipe translated, then rolled out in the world model step after step in
one state, with each plan line applied or refused, who wrote it, what changed, and the formula's progress."""

from __future__ import annotations

from pathlib import Path
from typing import NoReturn

import typer
from rich.console import Console
from rich.text import Text

from cook2ltl import files
from cook2ltl.errors import UserError
from cook2ltl.ltl.printer import to_unicode
from cook2ltl.pipeline.records import Variant
from cook2ltl.preprocess.recipe_file import read_recipe
from cook2ltl.text_safety import json_text, literal, styled, terminal
from cook2ltl.world.effects import fact_text

VERDICT_STYLE = {"satisfied": "bold green", "presumably_true": "green", "presumably_false": "yellow",
                 "violated": "bold red"}
WRITER_STYLE = {"model": "magenta", "library": "cyan", "recipe": "green", "planner": "blue"}


def is_recipe(target: str) -> bool:
    """A rollout target is a recipe when it names a file (or is -, standard input)."""
    if target == "-":
        return True
    try:
        return files.is_regular_file(Path(target).expanduser())
    except (RuntimeError, ValueError):  # ~name of no such user, or a NUL: no file, so a task or a formula
        return False


def rollout_recipe(recipe: str, primitives: str, model: str, library: Path | None, variant: Variant,
                   validate: bool | None, repairs: int | None, ground: bool, as_json: bool) -> NoReturn:
    """Translate the recipe with the world model on, roll it out, and exit 0 when every step reached its
    actions' effects and the formula holds, else 1."""
    # startup: `cook2ltl --help` imports this module; the pipeline loads when the command runs
    from cook2ltl.assembly.translators import TranslateOptions
    from cook2ltl.cli.translating import open_translator, translated
    from cook2ltl.pipeline.world_rollout import (
        NO_WORLD_HINT, ActionRolled, Began, RecipeRolledOut, StepRolled, recipe_rollout_json, roll_out_recipe,
    )
    from cook2ltl.reduce.primitives import load_primitives

    if not ground:
        raise UserError("A recipe rollout runs the recipe in the world model; --no-ground turns it off.",
                        "drop --no-ground (to run a formula in the THOR kitchen instead, give the formula).")
    text = read_recipe(recipe)
    chosen = load_primitives(primitives)
    if chosen.world is None:
        raise UserError(f"The {chosen.name} primitive set names no world model.", NO_WORLD_HINT)
    errors = terminal(stderr=True)
    options = TranslateOptions(variant, check=validate, repairs=repairs)
    with open_translator(chosen, model, library, options, errors) as translator:
        translation = translated(text, translator, errors)
    console = None if as_json else terminal()
    rollout = None
    for event in roll_out_recipe(translation, chosen, translator.grounding.world):
        if isinstance(event, RecipeRolledOut):
            rollout = event.rollout
        elif console is None:
            continue
        elif isinstance(event, Began):
            show_began(console, event, recipe, translation)
        elif isinstance(event, ActionRolled):
            show_action(console, event)
        elif isinstance(event, StepRolled):
            show_step_end(console, event.run)
    if as_json:
        typer.echo(json_text(recipe_rollout_json(rollout)))
    else:
        show_outcome(console, rollout)
    raise typer.Exit(0 if rollout.success else 1)


def show_began(console: Console, began, recipe: str, translation) -> None:
    name = "standard input" if recipe == "-" else Path(recipe).name
    console.print(styled((name, "bold"), (f" · {translation.primitives} primitives · {began.steps} steps, "
                                          f"{began.actions} actions · the world model", "dim")), highlight=False)
    console.print(literal("φ  ", style="dim") + literal(to_unicode(began.formula), style="yellow"), soft_wrap=True)
    if began.unobservable:
        never = ", ".join(atom.text for atom in began.unobservable)
        console.print(literal(f"the world cannot tell {never}: true only once waited for", "yellow"), highlight=False)


def show_action(console: Console, rolled) -> None:
    """An action as it is rolled out: its lines (✓ applied, ✗ refused), who wrote each, what changed, and the
    recipe formula's progress after it."""
    run, step = rolled.run, rolled.step
    if run.result is step.actions[0]:
        _step_title(console, step)
    head = literal("     → ") + literal(run.result.reduction.action.text(), style="bold")
    if run.avoided:
        console.print(head + literal("   avoided: the recipe says not to (not run)", style="dim"))
        return
    check = run.result.check
    if check is not None and check.effect:
        mark = literal(" ✓", style="green") if not run.missing else literal(" ✗", style="bold red")
        head += literal("   effect ", style="dim") + literal(", ".join(fact_text(f) for f in check.effect)) + mark
    console.print(head)
    if not run.lines:
        console.print(literal("         (no plan)", style="bold red"))
    for line in run.lines:
        mark = literal("✓ ", style="green") if line.applied else literal("✗ ", style="bold red")
        row = literal("       ") + mark + literal(f"{line.call.text():<28}") + literal(
            f" {line.written_by:<8}", style=WRITER_STYLE.get(line.written_by, "dim"))
        if not line.applied:
            row += literal(f" {line.problem}", style="red")
        else:
            changes = [f"+{fact_text(f)}" for f in line.added] + [f"−{fact_text(f)}" for f in line.removed]
            row += literal(" " + " ".join(changes), style="cyan")
        console.print(row, overflow="ellipsis", no_wrap=True)
    if run.lines:
        console.print(literal("         ") + _progress(run.lines[-1].verdict, run.lines[-1].remaining),
                      overflow="ellipsis", no_wrap=True)


def show_step_end(console: Console, step) -> None:
    if not step.actions:  # a step without actions had no title yet
        _step_title(console, step.result)
    for problem in step.problems:
        console.print(styled("     ", ("!", "bold red"), " ", problem), highlight=False)


def _progress(verdict, remaining) -> Text:
    """The verdict first, then what remains: a long remainder is cut at the line's end (--json has it whole)."""
    value = verdict.value
    return (literal(f"{value.replace('_', ' '):<17}", style=VERDICT_STYLE[value]) + literal("remaining ", style="dim")
            + literal(to_unicode(remaining)))


def _step_title(console: Console, step) -> None:
    console.print(literal(f"{step.step.index + 1:>3}. ", style="dim") + literal(step.step.sentence.text, style="bold"))


def show_outcome(console: Console, rollout) -> None:
    failing = [step for step in rollout.steps if step.problems]
    if failing:
        console.print(literal("problems by step", "bold"))
        for step in failing:
            _step_title(console, step.result)
            for problem in step.problems:
                console.print(styled("       ", ("!", "bold red"), " ", problem), highlight=False)
    console.print(literal("verdict ", style="dim") + _progress(rollout.verdict, rollout.remaining),
                  overflow="ellipsis", no_wrap=True)
    reached = sum(1 for step in rollout.steps if step.reached)
    outcome = literal("success", style="bold green") if rollout.success else literal("failure", style="bold red")
    console.print(outcome + literal(f" · {reached} of {len(rollout.steps)} steps reached their effects", style="dim"))
