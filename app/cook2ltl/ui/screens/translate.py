"""The Translate screen: a recipe editor and a run action; then the steps with their spans and frames, the
reductions as they arrive, and each step's formula, which can be exported as JSON or text."""

from __future__ import annotations

from pathlib import Path

from textual import work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.widgets import (
    Button, Checkbox, DataTable, Footer, Header, Select, Static, TabbedContent, TabPane, TextArea,
)
from textual.worker import get_current_worker

from cook2ltl.errors import UserError
from cook2ltl.preprocess.clean import visible_text
from cook2ltl.preprocess.recipe_file import read_recipe
from cook2ltl.ui.feeds import TranslateRequest, translation_feed
from cook2ltl.ui.literal import shown
from cook2ltl.ui.messages import ActionReduced, RecipeParsed, StepTranslated, TranslationDone
from cook2ltl.ui.screens.base import WorkScreen
from cook2ltl.ui.screens.dialogs import PathDialog
from cook2ltl.ui.widgets.formulas import FormulaList
from cook2ltl.ui.widgets.reductions import ReductionsTable, result_detail, summary
from cook2ltl.ui.widgets.status import WorkStatus
from cook2ltl.ui.widgets.steps_view import StepsView

PRIMITIVE_SETS = (("recipe primitives", "recipe"), ("AI2-THOR primitives", "ai2thor"))
LAB_MODE = "AR+A approved-only"  # AR+A reusing approved entries only
VARIANTS = (("AR+𝔸 (library)", "AR+A"), ("AR+𝔸, approved only", LAB_MODE), ("AR (no library)", "AR"),
            ("AR* (all by model)", "AR*"))


class TranslateScreen(WorkScreen):
    JOB = "translate"
    AUTO_FOCUS = "#recipe"  # ready for a paste
    BINDINGS = [
        Binding("ctrl+r", "run", "Run", id="translate.run"),
        Binding("ctrl+o", "open", "Open", id="translate.open"),
        Binding("ctrl+s", "export", "Export", id="translate.export"),
        Binding("ctrl+l", "toggle_syntax", "Unicode/Spot", id="translate.syntax"),
    ]
    PALETTE = (
        ("Translate: run", "Parse the recipe and translate it to LTL", "run"),
        ("Translate: open a recipe file", "Load a text file into the editor", "open"),
        ("Translate: export", "Write the translation as JSON (.json) or text (any other name)", "export"),
        ("Translate: Unicode / Spot syntax", "Show the formulas in the other syntax", "toggle_syntax"),
    )

    def compose(self) -> ComposeResult:
        yield Header()
        with Horizontal(id="translate-options", classes="options"):
            lab_sets = tuple((shown(path.name), str(path)) for path in self.app.translate_settings.primitives)
            yield Select(PRIMITIVE_SETS + lab_sets, value="recipe", allow_blank=False, id="primitives",
                         tooltip="The robot's primitive actions: the paper's recipe set, AI2-THOR's (rollouts), "
                                 "or a set the settings' [translate] primitives name.")
            yield Select(VARIANTS, value="AR+A", allow_blank=False, id="variant",
                         tooltip="The paper's ablation: AR+𝔸 reuses and grows the action library (approved only: "
                                 "reuses only entries a reviewer approved); AR passes primitives through; AR* asks "
                                 "the model for every action.")
            models = self.app.services.model_names
            yield Select([(shown(name), name) for name in models], value=self.app.model_name, allow_blank=False,
                         id="model")
            repairs = self.app.translate_settings.repairs
            yield Checkbox("kitchen check", True, id="validate",
                           tooltip="Run each new reduction in the THOR kitchen before caching it; a failing plan "
                                   f"goes back to the model with its problems ({repairs} repairs, the settings' "
                                   "[translate] repairs).")
            yield Button("Run", variant="primary", id="run")
            yield Button("Open…", id="open")
        with Horizontal(id="translate-body"):
            editor = TextArea(visible_text(self.app.recipe_text), id="recipe", soft_wrap=True)
            editor.border_title = "Recipe"
            yield editor
            with TabbedContent(id="results", initial="steps"):
                with TabPane("Steps", id="steps"):
                    with VerticalScroll():
                        yield StepsView("Run the recipe (ctrl+r) to see its steps, spans and frames.", id="steps-view")
                with TabPane("Reductions", id="reductions"):
                    with Vertical():
                        yield ReductionsTable(id="reductions-table")
                        yield Static("", id="reduction-detail")
                        yield Static("", id="reduction-summary")
                with TabPane("Formulas", id="formulas"):
                    with VerticalScroll():
                        yield FormulaList(id="formula-list")
        yield WorkStatus()
        yield Footer()

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        if action == "run":
            return not self.busy
        return super().check_action(action, parameters)

    def on_button_pressed(self, event: Button.Pressed) -> None:
        self.run_action(event.button.id)

    def on_select_changed(self, event: Select.Changed) -> None:
        if event.select.id == "model":
            self.app.model_name = event.value
        elif event.select.id == "variant":  # as on the command line: checked by default where entries are cached
            self.query_one("#validate", Checkbox).value = event.value in ("AR+A", LAB_MODE)

    def action_run(self) -> None:
        if self.busy:  # the palette can ask while a run is on
            return
        text = self.query_one("#recipe", TextArea).text
        if not text.strip():
            self.notify("Paste a recipe or open a file first.", severity="warning")
            return
        chosen = self.query_one("#variant", Select).value
        request = TranslateRequest(text, self.query_one("#primitives", Select).value,
                                   "AR+A" if chosen == LAB_MODE else chosen, self.query_one("#model", Select).value,
                                   self.query_one("#validate", Checkbox).value, approved_only=chosen == LAB_MODE,
                                   repairs=self.app.translate_settings.repairs,
                                   ground=self.app.translate_settings.ground,
                                   reuse=self.app.translate_settings.reuse)
        self.query_one(StepsView).update("parsing …")
        self.query_one(ReductionsTable).clear()
        self.query_one("#reduction-summary", Static).update("")
        self.query_one("#reduction-detail", Static).update("")
        self.query_one(FormulaList).clear()
        self.query_one("#run", Button).disabled = True
        self.begin("starting …")
        self.translate(request)

    @work(thread=True, exclusive=True, exit_on_error=False, group=JOB)
    def translate(self, request: TranslateRequest) -> None:
        for message in translation_feed(self.app.services, request, get_current_worker().cancelled_event):
            self.post_message(message)

    def work_ended(self) -> None:
        self.query_one("#run", Button).disabled = False

    def on_recipe_parsed(self, message: RecipeParsed) -> None:
        self.query_one(StepsView).show_recipe(message.parsed)
        self.query_one(ReductionsTable).show_pending(message.parsed)

    def on_action_reduced(self, message: ActionReduced) -> None:
        table = self.query_one(ReductionsTable)
        table.show_result(message.event.done, message.event.result)
        self._show_reduction()

    def on_data_table_row_highlighted(self, event: DataTable.RowHighlighted) -> None:
        if event.data_table.id == "reductions-table":
            self._show_reduction()

    def _show_reduction(self) -> None:
        self.query_one("#reduction-detail", Static).update(result_detail(self.query_one(ReductionsTable).highlighted()))

    def on_step_translated(self, message: StepTranslated) -> None:
        self.query_one(FormulaList).add_step(message.result)

    def on_translation_done(self, message: TranslationDone) -> None:
        translation = message.translation
        self.query_one(FormulaList).finish(translation.formula)
        self.query_one("#reduction-summary", Static).update(summary(translation))
        self.query_one(WorkStatus).show(f"done in {translation.stats.seconds:.1f} s")

    def action_toggle_syntax(self) -> None:
        formulas = self.query_one(FormulaList)
        formulas.spot = not formulas.spot

    def action_open(self) -> None:
        self.app.push_screen(PathDialog("Open a recipe file", f"{Path.cwd()}/", "Open"), self._open)

    def _open(self, path: Path | None) -> None:
        if path is None:
            return
        try:
            text = read_recipe(str(path))
        except UserError as error:
            self.app.show_error(error)
            return
        self.app.recipe_path = path
        self.query_one("#recipe", TextArea).load_text(visible_text(text))
        self.notify(f"opened {path}")

    def action_export(self) -> None:
        if self.app.translation is None:
            self.notify("Nothing to export yet: run a translation first.", severity="warning")
            return
        stem = self.app.recipe_path.stem if self.app.recipe_path else "recipe"
        self.app.push_screen(PathDialog("Export the translation (.json for JSON, else text)",
                                        str(Path.cwd() / f"{stem}.ltl.json"), "Export"), self._export)

    def _export(self, path: Path | None) -> None:
        # startup: the app opens before the report and JSON writers (lark) load
        from cook2ltl.ui.export import write_translation

        if path is None:
            return
        try:
            write_translation(self.app.translation, path)
        except UserError as error:
            self.app.show_error(error)
            return
        self.notify(f"wrote {path}")
