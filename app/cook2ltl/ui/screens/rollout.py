"""The Rollout screen: a kitchen task (planned by Algorithm 1, or its reference plan), the current recipe's
formulas, or a formula typed in, executed headless in a kitchen; the action log, the objects it touched,
and the formula's progress after every action, then the verdict. A recipe (the current translation, or a file
opened here and translated) also runs in the world model, step after step in one state, line by line."""

from __future__ import annotations

from pathlib import Path

from textual import work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.content import Content
from textual.widgets import Button, Checkbox, DataTable, Footer, Header, Input, Select
from textual.worker import get_current_worker

from cook2ltl.errors import UserError
from cook2ltl.preprocess.recipe_file import read_recipe
from cook2ltl.text_safety import literal, visible
from cook2ltl.ui.feeds import RecipeRolloutRequest, RolloutRequest, TranslateRequest, recipe_rollout_feed, rollout_feed
from cook2ltl.ui.literal import shown
from cook2ltl.ui.messages import (
    RecipeActionRolled, RecipeRolloutBegan, RecipeRolloutDone, RecipeStepRolled, RolloutBegan, RolloutDone,
    RolloutRefused, RolloutStepped,
)
from cook2ltl.ui.screens.base import WorkScreen
from cook2ltl.ui.screens.dialogs import PathDialog
from cook2ltl.ui.widgets.progress_view import FormulaProgress, verdict_content
from cook2ltl.ui.widgets.status import WorkStatus

DEFAULT_SCENE = "FloorPlan1"
# (name, width): Textual content cells are not measured by the table, so theirs are fixed.
LOG_COLUMNS = (("#", None), ("", 1), ("action", None), ("verdict", 16), ("holds after · or why refused", None))
FORMULA = "formula"  # the target typed in the formula field
WORLD = "world"  # the current translation in the world model
FILE = "file"  # the recipe file opened here, translated then rolled out in the world model


class RolloutScreen(WorkScreen):
    JOB = "rollout"
    BINDINGS = [Binding("ctrl+r", "run", "Run", id="rollout.run"),
                Binding("ctrl+o", "open", "Recipe file", id="rollout.open")]
    PALETTE = (("Rollout: run", "Execute the chosen task or formula in the kitchen", "run"),
               ("Rollout: a recipe file in the world model", "Translate a recipe file, then run it step after step "
                "in the world model", "open"))

    def __init__(self) -> None:
        super().__init__()
        self.recipe_file: Path | None = None  # opened with ctrl+o

    def compose(self) -> ComposeResult:
        # startup: the app opens before the kitchen scenes (~6 ms) load
        from cook2ltl.simulator.scenes import scene_names

        yield Header()
        with Horizontal(id="rollout-options", classes="options"):
            yield Select(self._targets(), value=self._targets()[0][1], allow_blank=False, id="target")
            yield Checkbox("reference plan", id="reference",
                           tooltip="Run the task's hand-written plan instead of planning it (no model needed).")
            yield Select([("task's kitchen", ""), *((name, name) for name in scene_names())], value="",
                         allow_blank=False, id="scene")
            yield Button("Run", variant="primary", id="run-rollout")
        yield Input(placeholder="or an LTL formula over the ai2thor primitives, e.g. "
                                "F(pick_up(apple) & F put(apple, fridge))", id="formula")
        with Horizontal(id="rollout-body"):
            with Vertical(id="rollout-main"):
                with VerticalScroll(id="progress-scroll"):
                    yield FormulaProgress("Choose a task or a formula and run it (ctrl+r).", id="progress")
                yield DataTable(id="log", cursor_type="row")
            yield DataTable(id="objects", cursor_type="none")
        yield WorkStatus()
        yield Footer()

    def on_mount(self) -> None:
        log = self.query_one("#log", DataTable)
        for name, width in LOG_COLUMNS:
            log.add_column(name, key=name, width=width)
        self.query_one("#objects", DataTable).add_columns("object", "where", "state")

    def on_screen_resume(self) -> None:
        """The current recipe's formulas appear once a translation has finished."""
        self._refresh_targets()

    def _refresh_targets(self) -> None:
        target = self.query_one("#target", Select)
        choice = target.value
        targets = self._targets()
        target.set_options(targets)
        target.value = choice if any(value == choice for _, value in targets) else targets[0][1]

    def _targets(self) -> list[tuple[Content, str]]:
        from cook2ltl.execution.tasks import load_tasks  # startup: the app opens before the tasks (pydantic, lark) load

        targets = [(f"task {t.id}: {t.instruction}", f"task:{t.id}") for t in load_tasks()]
        translation = self.app.translation
        if translation is not None and translation.world_start is not None:
            targets.append((f"recipe in the world model, line by line ({len(translation.steps)} steps)", WORLD))
        if translation is not None:
            targets.append((f"recipe: every step ({len(translation.steps)})", "recipe"))
            targets += [(f"recipe step {s.step.index + 1}: {s.step.sentence.text}", f"recipe:{i}")
                        for i, s in enumerate(translation.steps)]
        if self.recipe_file is not None:
            targets.append((f"recipe file {self.recipe_file.name} in the world model", FILE))
        targets.append(("the formula typed below", FORMULA))
        return [(_short(label), value) for label, value in targets]

    def on_input_changed(self, event: Input.Changed) -> None:
        if event.value.strip():
            self.query_one("#target", Select).value = FORMULA

    def on_input_submitted(self) -> None:
        self.action_run()

    def on_button_pressed(self) -> None:
        self.action_run()

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        if action == "run":
            return not self.busy
        return super().check_action(action, parameters)

    def action_run(self) -> None:
        if self.busy:
            return
        try:
            request = self.request()
        except UserError as error:
            self.app.show_error(error)
            return
        for table in self.query(DataTable):
            table.clear()
        self.query_one(FormulaProgress).update("")
        self.query_one("#run-rollout", Button).disabled = True
        self.begin("starting …")
        if isinstance(request, RecipeRolloutRequest):
            self.roll_out_recipe(request)
        else:
            self.roll_out(request)

    def action_open(self) -> None:
        if not self.busy:
            self.app.push_screen(PathDialog("A recipe file to run in the world model", f"{Path.cwd()}/", "Run"),
                                 self._open)

    def _open(self, path: Path | None) -> None:
        if path is None:
            return
        self.recipe_file = path
        self._refresh_targets()
        self.query_one("#target", Select).value = FILE
        self.action_run()

    def request(self) -> RolloutRequest | RecipeRolloutRequest:
        """The chosen target as a request; UserError for what cannot run."""
        # startup: the app opens before the trial and the tasks (pydantic, lark, sqlite-utils) load
        from cook2ltl.assembly.trial import reference_formula
        from cook2ltl.execution.tasks import find_task

        target = self.query_one("#target", Select).value
        scene = self.query_one("#scene", Select).value
        if target.startswith("task:"):
            task = find_task(target.removeprefix("task:"))
            formula = reference_formula(task) if self.query_one("#reference", Checkbox).value else None
            return RolloutRequest(scene or task.scene, task, formula, self.app.model_name,
                                  self.app.translate_settings.repairs)
        if target == WORLD:
            translation = self.app.translation
            return RecipeRolloutRequest("the recipe", self.app.translation_primitives or translation.primitives,
                                        translation)
        if target == FILE:
            return self._file_request()
        if target.startswith("recipe"):
            return RolloutRequest(scene or DEFAULT_SCENE, formula=self._recipe_formula(target))
        return RolloutRequest(scene or DEFAULT_SCENE, formula=self._typed_formula())

    def _file_request(self) -> RecipeRolloutRequest:
        """The opened file translated with the recipe primitives and the world model, as `cook2ltl rollout
        RECIPE-FILE` does; UserError for a file that is no recipe."""
        text = read_recipe(str(self.recipe_file))
        settings = self.app.translate_settings
        translate = TranslateRequest(text, "recipe", "AR+A", self.app.model_name, repairs=settings.repairs,
                                     ground=True)
        return RecipeRolloutRequest(self.recipe_file.name, "recipe", translate=translate)

    def _recipe_formula(self, target: str):
        translation = self.app.translation
        if translation is None:
            raise UserError("There is no translation yet.", "run the recipe on the Translate screen (F2).")
        if translation.primitives != "ai2thor":
            raise UserError(f"The recipe was translated with the {translation.primitives} primitives; the kitchen "
                            "executes the ai2thor primitives.",
                            "choose “AI2-THOR primitives” on the Translate screen and run the recipe again.")
        if target == "recipe":
            return translation.formula
        return translation.steps[int(target.removeprefix("recipe:"))].formula

    def _typed_formula(self):
        # startup: the app opens before the LTL parser (lark) loads
        from cook2ltl.ltl.parser import LTLSyntaxError, parse

        text = self.query_one("#formula", Input).value.strip()
        if not text:
            raise UserError("No formula to run.", "type one, e.g. F(pick_up(apple) & F put(apple, fridge)).")
        try:
            return parse(text)
        except LTLSyntaxError as error:
            raise UserError(f"Not a formula: {error}", "e.g. F(pick_up(apple) & F put(apple, fridge)).") from None

    @work(thread=True, exclusive=True, exit_on_error=False, group=JOB)
    def roll_out(self, request: RolloutRequest) -> None:
        for message in rollout_feed(self.app.services, request, get_current_worker().cancelled_event):
            self.post_message(message)

    @work(thread=True, exclusive=True, exit_on_error=False, group=JOB)
    def roll_out_recipe(self, request: RecipeRolloutRequest) -> None:
        for message in recipe_rollout_feed(self.app.services, request, get_current_worker().cancelled_event):
            self.post_message(message)

    def work_ended(self) -> None:
        self.query_one("#run-rollout", Button).disabled = False

    def on_rollout_began(self, message: RolloutBegan) -> None:
        self.query_one(FormulaProgress).begin(message)

    def on_rollout_stepped(self, message: RolloutStepped) -> None:
        step = message.step
        log = self.query_one("#log", DataTable)
        facts = ", ".join(sorted(atom.text for atom in step.facts))
        log.add_row(str(step.index), Content("✓").stylize("$text-success"), literal(step.attempt.atom.text),
                    verdict_content(step.verdict.value), literal(facts))
        log.move_cursor(row=log.row_count - 1)
        objects = self.query_one("#objects", DataTable)
        objects.clear()
        for state in message.objects:
            objects.add_row(literal(state.name), literal(state.where), literal(state.state))
        self.query_one(FormulaProgress).step(step)

    def on_rollout_refused(self, message: RolloutRefused) -> None:
        log = self.query_one("#log", DataTable)
        attempt = message.attempt
        log.add_row("", Content("✗").stylize("$text-error"), literal(attempt.atom.text), Content("refused"),
                    literal(attempt.error))
        log.move_cursor(row=log.row_count - 1)

    def on_rollout_done(self, message: RolloutDone) -> None:
        self.query_one(FormulaProgress).finish(message.trial)
        trial = message.trial
        goal = "" if trial.goal is None else f", the task's goal {'holds' if trial.goal.met else 'does not hold'}"
        verdict = trial.rollout.verdict.value.replace("_", " ")
        self.query_one(WorkStatus).show(f"{'success' if trial.success else 'failure'}: the formula is {verdict}{goal}")


    def on_recipe_rollout_began(self, message: RecipeRolloutBegan) -> None:
        self.query_one(FormulaProgress).begin_recipe(message)

    def on_recipe_action_rolled(self, message: RecipeActionRolled) -> None:
        """The step's sentence before its first action, the action with its effect, then one row a line."""
        from cook2ltl.world.effects import fact_text  # startup: the app opens before the world model (~15 ms) loads

        run, step = message.rolled.run, message.rolled.step
        log = self.query_one("#log", DataTable)
        number = step.step.index + 1
        if run.result is step.actions[0]:
            log.add_row(str(number), "", literal(step.step.sentence.text, style="bold"), "", "")
        check = run.result.check
        effect = ", ".join(fact_text(f) for f in check.effect) if check is not None else ""
        outcome = "avoided: not run" if run.avoided else \
            f"effect {effect or '—'}: {'reached' if run.reached else 'not reached'}"
        log.add_row("", "", literal(f"→ {run.result.reduction.action.text()}"), "", literal(outcome))
        for index, line in enumerate(run.lines, 1):
            mark = Content("✓").stylize("$text-success") if line.applied else Content("✗").stylize("$text-error")
            changes = [f"+{fact_text(f)}" for f in line.added] + [f"−{fact_text(f)}" for f in line.removed]
            log.add_row(f"{number}.{index}", mark, literal(f"{line.call.text()} · {line.written_by or '?'}"),
                        verdict_content(line.verdict.value) if line.applied else Content("refused"),
                        literal(" ".join(changes) if line.applied else line.problem))
            if line.applied:
                self.query_one(FormulaProgress).step(line)
        log.move_cursor(row=log.row_count - 1)

    def on_recipe_step_rolled(self, message: RecipeStepRolled) -> None:
        log = self.query_one("#log", DataTable)
        for problem in message.run.problems:
            log.add_row("", Content("!").stylize("$text-error"), literal("problem"), "", literal(problem))
        log.move_cursor(row=log.row_count - 1)

    def on_recipe_rollout_done(self, message: RecipeRolloutDone) -> None:
        rollout = message.rollout
        self.query_one(FormulaProgress).finish_recipe(rollout)
        verdict = rollout.verdict.value.replace("_", " ")
        reached = sum(1 for step in rollout.steps if step.reached)
        self.query_one(WorkStatus).show(f"{'success' if rollout.success else 'failure'}: the formula is {verdict}, "
                                        f"{reached} of {len(rollout.steps)} steps reached their effects")


def _short(label: str, width: int = 46) -> Content:
    """One line in the target list, however long the recipe step, shown literally."""
    label = visible(label)
    return shown(label if len(label) <= width else label[: width - 1] + "…")
