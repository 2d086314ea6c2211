"""`cook2ltl rollout`: a task planned by Algorithm 1, or a formula, executed in a kitchen through ai2thor's
Controller, with what is satisfied and what remains after every action, the verdict and the task's goal; or a
recipe file, translated and rolled out in the world model (cli/recipe_rollout.py)."""

from __future__ import annotations

from enum import StrEnum
from pathlib import Path
from typing import Optional

import typer
from rich.console import Console

from cook2ltl import paths
from cook2ltl.assembly.backends import DEFAULT_MODEL
from cook2ltl.cli.recipe_rollout import is_recipe, rollout_recipe
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.errors import UserError
from cook2ltl.ltl.parser import LTLSyntaxError, parse
from cook2ltl.ltl.printer import to_unicode
from cook2ltl.pipeline.records import Variant
from cook2ltl.text_safety import json_text, literal, styled, terminal

DEFAULT_SCENE = "FloorPlan1"
VERDICT_STYLE = {"satisfied": "bold green", "presumably_true": "green", "presumably_false": "yellow",
                 "violated": "bold red"}


class Backend(StrEnum):
    EMBEDDED = "embedded"
    THOR = "thor"
    AUTO = "auto"


def rollout_command(
    target: Optional[str] = typer.Argument(None, metavar="TASK|FORMULA|RECIPE-FILE", show_default=False,
                                           help="A task's id or instruction (see --list), an LTL formula, or a "
                                                "recipe file (- for standard input)."),
    scene: Optional[str] = typer.Option(None, "--scene", help="FloorPlan1 … FloorPlan30 (default: the task's own, "
                                        f"else {DEFAULT_SCENE})."),
    backend: Backend = typer.Option(Backend.EMBEDDED, "--backend", case_sensitive=False,
                                    help="embedded kitchen, a real AI2-THOR build, or auto (THOR if installed)."),
    reference: bool = typer.Option(False, "--reference", help="Run the task's hand-written reference plan instead "
                                   "of planning it."),
    model: str = typer.Option(DEFAULT_MODEL, "--model", help="Language model of the manifest (`cook2ltl models`)."),
    library: Optional[Path] = typer.Option(None, "--library", help="Action library file (default: $COOK2LTL_LIBRARY,"
                                           " else library.sqlite in the user data folder)."),
    variant: Variant = typer.Option(Variant.AR_LIBRARY, "--variant", case_sensitive=False,
                                    help="AR passes primitives through; AR+A also reuses and grows the library."),
    validate: Optional[bool] = typer.Option(None, "--validate/--no-validate", help="AR+A: check a new reduction in "
                                            "a kitchen of its own before it is cached, as `translate` does (default: "
                                            "on for a task; for a recipe, as `translate`)."),
    ground: bool = typer.Option(True, "--ground/--no-ground",
                                help="Check and complete the plan in the world model of the kitchen it runs in."),
    repairs: Optional[int] = typer.Option(None, "--repairs", min=0, max=10, show_default=False,
                                          help="Times a plan the check refuses goes back to the model (default: "
                                               "the settings' [translate] repairs, else 2)."),
    primitives: Optional[str] = typer.Option(None, "--primitives", help="A recipe's primitive set: recipe (default), "
                                             "ai2thor, or a TOML file of your robot's set."),
    list_tasks: bool = typer.Option(False, "--list", help="List the tasks and exit."),
    as_json: bool = typer.Option(False, "--json", help="Print machine-readable JSON."),
) -> None:
    """Execute a task or formula in an AI2-THOR kitchen, or a recipe in the world model, and follow the formula's
    progress action by action.

    Exits with 0 when the task's goal holds at the end (for a formula: when the formula does; for a recipe: when
    every step reached its effects and the formula holds), else 1.
    """
    # startup: `cook2ltl --help` imports this module; the kitchen and the planner load when the command runs
    from cook2ltl.assembly.planning import open_planner
    from cook2ltl.assembly.trial import TrialDone, run_trial, trial_json
    from cook2ltl.execution.launcher import start_kitchen
    from cook2ltl.execution.tasks import set_up

    library = paths.user_path(library, "--library") if library else None
    if list_tasks:
        show_tasks(terminal(), as_json)
        return
    if target is None:
        raise UserError("No task, formula or recipe given.",
                        "name a task (cook2ltl rollout --list), write a formula, or give a recipe file.")
    if is_recipe(target):
        if reference or scene:
            raise UserError("--reference and --scene are for kitchen tasks; a recipe runs in the world model.",
                            "drop them, or name a task (cook2ltl rollout --list).")
        rollout_recipe(target, primitives or "recipe", model, library, variant, validate, repairs, ground, as_json)
    if primitives is not None:
        raise UserError("--primitives is for a recipe file; a task or formula uses the ai2thor primitives.",
                        "drop --primitives, or give a recipe file.")
    task, formula = read_target(target, reference)
    if repairs is None:
        repairs = load_settings().translate.repairs
    scene = _scene(scene or (task.scene if task else DEFAULT_SCENE))
    errors = terminal(stderr=True)
    with errors.status(literal(f"starting the {backend.value} kitchen …")):
        controller = start_kitchen(scene, backend.value)
    try:
        plan = None
        if formula is None:
            with errors.status(literal(f"planning “{task.instruction}” with {model} …")), \
                    open_planner(model, library, variant, validate is not False, repairs, ground) as planner:
                set_up(controller, task)  # planned in the kitchen as the task leaves it (a dirty mug)
                plan = planner.plan(task.instruction, scene, controller.last_event.metadata["objects"])
            formula = plan.formula
        console = None if as_json else terminal()
        if console is not None:
            show_header(console, task, plan, formula, scene, backend.value)
        trial = None
        for event in run_trial(controller, formula, scene, task, plan):
            if isinstance(event, TrialDone):
                trial = event.trial
            elif console is not None:
                show_event(console, event, len(formula.atoms))
    finally:
        controller.stop()
    if as_json:
        typer.echo(json_text(trial_json(trial, backend.value)))
    else:
        show_outcome(console, trial)
    raise typer.Exit(0 if trial.success else 1)


def read_target(target: str, reference: bool):
    """(task or None, formula or None): a task is planned later unless its reference plan is asked for."""
    # startup: `cook2ltl --help` imports this module; the tasks and the trial load when the command runs
    from cook2ltl.assembly.trial import reference_formula
    from cook2ltl.execution.tasks import find_task, load_tasks

    task = find_task(target)
    if task is not None:
        return task, reference_formula(task) if reference else None
    ids = ", ".join(t.id for t in load_tasks())
    if reference:
        raise UserError(f"--reference needs a task; {target!r} is not one.", f"tasks: {ids}.")
    try:
        return None, parse(target)
    except LTLSyntaxError as error:
        raise UserError(f"{target!r} is neither a task nor a formula ({error}).",
                        f"tasks: {ids}; or a formula such as 'F(pick_up(apple) & F put(apple, fridge))'.") from None


def _scene(name: str) -> str:
    # startup: `cook2ltl --help` imports this module; the kitchen scenes load when the command runs
    from cook2ltl.simulator.scenes import UnknownScene, canonical_scene

    try:
        return canonical_scene(name)
    except UnknownScene as error:
        raise UserError(str(error), "kitchens are FloorPlan1 … FloorPlan30.") from None


def show_tasks(console: Console, as_json: bool) -> None:
    # startup: `cook2ltl --help` imports this module; the tasks (pydantic) load when the command runs
    from cook2ltl.execution.tasks import PARAPHRASES, load_tasks, task_json

    tasks = load_tasks()
    if as_json:
        typer.echo(json_text([task_json(t) for t in tasks]))
        return
    groups = (("", [t for t in tasks if t.source != PARAPHRASES]),
              ("\nparaphrases (held out: paraphrased and compound instructions)",
               [t for t in tasks if t.source == PARAPHRASES]))
    for heading, group in groups:
        if heading and group:
            console.print(heading, style="bold", highlight=False)
        width = max([34] + [len(t.instruction) for t in group])
        for task in group:
            goal = "; ".join(c.text() for c in task.goal)
            console.print(styled((f"{task.id:<20}", "bold"), f" {task.instruction:<{width}} ",
                                 (f"{task.scene:<12} {task.category:<7} {goal}", "dim")),
                          highlight=False, soft_wrap=True)


def show_header(console: Console, task, plan, formula, scene: str, backend: str) -> None:
    title = f"task {task.id} · “{task.instruction}”" if task else "formula"
    console.print(styled((title, "bold"), (f" · {scene} · {backend} kitchen", "dim")), highlight=False)
    if task is not None:
        console.print(literal("goal  ", style="dim") + literal("; ".join(c.text() for c in task.goal)))
    if plan is not None:
        calls = " · ".join(call.text() for call in plan.calls) or "(no admissible plan)"
        console.print(literal("plan  ", style="dim") + literal(calls) + literal(
            f"   [{plan.model}, {plan.variant.value}: {', '.join(plan.sources)}; {plan.seconds:.1f} s]", style="dim"))
        for problem in plan.problems:
            console.print(styled("      ", ("!", "bold red"), " ", problem), highlight=False)
    console.print(literal("φ     ", style="dim") + literal(to_unicode(formula), style="yellow"), soft_wrap=True)


def show_event(console: Console, event, atoms: int) -> None:
    """One rollout event as it happens; `atoms` is how many atoms the formula has."""
    # startup: `cook2ltl --help` imports this module; the rollout loads when the command runs
    from cook2ltl.execution.rollout import ActionRefused, RolloutStarted, Stepped

    if isinstance(event, RolloutStarted) and event.unobservable:
        never = ", ".join(a.text for a in event.unobservable)
        console.print(literal(f"the kitchen cannot report {never}: it never holds", "yellow"), highlight=False)
    elif isinstance(event, ActionRefused):
        console.print(literal("    ✗ ", style="bold red") + literal(event.attempt.error))
    elif isinstance(event, Stepped):
        step = event.step
        line = styled((f"{step.index:>3} ", "dim"), ("✓ ", "green"), (step.attempt.atom.text, "bold"))
        line += literal(f"   {len(step.met)}/{atoms} atoms met", style="dim")
        if step.facts:
            line += literal("   now " + ", ".join(sorted(a.text for a in step.facts)), style="cyan")
        console.print(line)
        remaining = literal("      remaining ", style="dim") + literal(to_unicode(step.remaining))
        remaining += literal(f"   {step.verdict.value.replace('_', ' ')}", style=VERDICT_STYLE[step.verdict.value])
        console.print(remaining, soft_wrap=True)


def show_outcome(console: Console, trial) -> None:
    # startup: `cook2ltl --help` imports this module; the trial loads when the command runs
    from cook2ltl.assembly.trial import explain

    result = trial.rollout
    verdict = result.verdict.value
    console.print(literal("verdict ", style="dim") + literal(verdict.replace("_", " "), style=VERDICT_STYLE[verdict])
                  + literal(f" — {explain(result)}", style="dim"))
    if trial.goal is not None:
        for condition, met in trial.goal.conditions:
            mark = literal("✓ ", style="green") if met else literal("✗ ", style="bold red")
            console.print(literal("goal    ", style="dim") + mark + literal(condition.text()))
    planning = f" · {trial.plan.seconds:.1f} s planning" if trial.plan else ""
    outcome = literal("success", style="bold green") if trial.success else literal("failure", style="bold red")
    console.print(outcome + literal(f" · {len(result.steps)} actions · {result.seconds:.2f} s in the kitchen"
                                    f"{planning}", style="dim"))
