"""The Textual app: Translate, Library and Rollout screens as modes, the help screen and the error dialog.

Nothing heavy is imported or loaded at start-up (the first screen paints before any model is touched);
`Services` builds the backends in a worker the first time a run needs them.
"""

from __future__ import annotations

import traceback
from collections.abc import Mapping
from dataclasses import replace
from datetime import datetime
from pathlib import Path
from typing import TYPE_CHECKING

from textual.app import App
from textual.binding import Binding
from textual.screen import Screen

from cook2ltl import offline, paths
from cook2ltl.domain.settings import TranslateSettings
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.errors import UserError
from cook2ltl.preprocess.recipe_file import read_recipe
from cook2ltl.text_safety import visible
from cook2ltl.ui.commands import MainCommands
from cook2ltl.ui.messages import TranslationDone
from cook2ltl.ui.screens.base import WorkScreen
from cook2ltl.ui.screens.dialogs import ErrorDialog
from cook2ltl.ui.screens.help import HelpScreen
from cook2ltl.ui.screens.library import LibraryScreen
from cook2ltl.ui.screens.rollout import RolloutScreen
from cook2ltl.ui.screens.translate import TranslateScreen
from cook2ltl.ui.services import Services, production_services

if TYPE_CHECKING:
    from cook2ltl.pipeline.records import Translation


class Cook2LTLApp(App):
    CSS_PATH = "app.tcss"
    TITLE = "cook2ltl"
    SUB_TITLE = "recipes to LTL task specifications"
    MODES = {"translate": TranslateScreen, "library": LibraryScreen, "rollout": RolloutScreen}
    DEFAULT_MODE = "translate"
    COMMANDS = App.COMMANDS | {MainCommands}
    BINDINGS = [
        Binding("f1", "help", "Help", id="app.help"),
        Binding("f2", "switch_mode('translate')", "Translate", id="app.translate"),
        Binding("f3", "switch_mode('library')", "Library", id="app.library"),
        Binding("f4", "switch_mode('rollout')", "Rollout", id="app.rollout"),
    ]

    def __init__(self, services: Services, recipe_text: str = "", recipe_path: Path | None = None,
                 keymap: Mapping[str, str] | None = None, translate: TranslateSettings | None = None) -> None:
        super().__init__()
        self.keymap = dict(keymap or {})
        unknown = sorted(set(self.keymap) - binding_ids())
        if unknown:
            raise UserError(f"The settings' [keymap] names no binding {', '.join(unknown)}.",
                            f"the binding ids are {', '.join(sorted(binding_ids()))}.")
        self.services = services
        self.translate_settings = translate or TranslateSettings()  # the lab's primitive sets and repairs
        self.recipe_text = recipe_text
        self.recipe_path = recipe_path
        self.model_name = services.model_names[0]  # chosen on Translate, used by Rollout's planning too
        self.translation: Translation | None = None  # the last one finished, for the Rollout screen
        self.translation_primitives = ""  # the primitive set it was made with (recipe, ai2thor or a file)

    def on_mount(self) -> None:
        self.set_keymap(self.keymap)

    def notify(self, message: str, *, title: str = "", **options) -> None:
        """Every notification, a screen's or a widget's, shows its text literally: a path or a library entry
        in it may hold markup or control characters."""
        options["markup"] = False
        super().notify(visible(message), title=visible(title), **options)

    def on_translation_done(self, message: TranslationDone) -> None:
        self.translation, self.translation_primitives = message.translation, message.primitives

    def action_help(self) -> None:
        if isinstance(self.screen, HelpScreen):
            return
        sections = [("Everywhere", [*self.BINDINGS, Binding("ctrl+p", "", "Command palette"),
                                    Binding("ctrl+q", "", "Quit")])]
        for title, screen in (("Translate", TranslateScreen), ("Library", LibraryScreen), ("Rollout", RolloutScreen)):
            sections.append((title, [*screen.BINDINGS, *WorkScreen.BINDINGS]))
        self.push_screen(HelpScreen([(title, self._as_mapped(bindings)) for title, bindings in sections]))

    def _as_mapped(self, bindings: list[Binding]) -> list[Binding]:
        """The bindings with the keys the settings' [keymap] gave them, as the app answers them."""
        return [replace(b, key=self.keymap[b.id]) if b.id in self.keymap else b for b in bindings]

    def show_error(self, error: BaseException) -> None:
        """A dialog for any failure: a UserError's message and hint, else the error in a line and the
        traceback written to a log file (a traceback on screen would be a bug)."""
        if isinstance(error, UserError):
            self.push_screen(ErrorDialog("Cannot do that", error.message, error.hint))
            return
        log = _log_traceback(error)
        hint = f"This is a bug in cook2ltl; the details are in {log}." if log else "This is a bug in cook2ltl."
        self.push_screen(ErrorDialog("Unexpected error", f"{type(error).__name__}: {error}", hint))

    def on_unmount(self) -> None:
        self.services.close()


def binding_ids() -> set[str]:
    """The id of every key binding of the app and its screens: what a [keymap] may remap."""
    classes, pending = [Cook2LTLApp], list(Screen.__subclasses__())
    while pending:
        screen = pending.pop()
        pending.extend(screen.__subclasses__())
        if screen.__module__.startswith("cook2ltl.ui"):
            classes.append(screen)
    return {binding.id for cls in classes for binding in cls.BINDINGS if isinstance(binding, Binding) and binding.id}


def _log_traceback(error: BaseException) -> Path | None:
    path = paths.data_dir() / "ui-errors.log"
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        with path.open("a", encoding="utf-8") as handle:
            handle.write(f"--- {datetime.now().isoformat(timespec='seconds')}\n")
            handle.write("".join(traceback.format_exception(error)))
    except OSError:
        return None
    return path


def run_app(recipe_path: str | Path | None = None) -> None:
    """Open the app, on a recipe file if one is given (read now, so a bad file is a CLI error)."""
    offline.enforce()  # before any model library is imported, however the app was started
    text = ""
    if recipe_path is not None:
        if str(recipe_path) == "-":
            raise UserError("The app reads its keys from the terminal, not a recipe from standard input.",
                            "give a recipe file, or paste the recipe into the app's editor.")
        text = read_recipe(str(recipe_path))
    settings = load_settings()
    Cook2LTLApp(production_services(), text, Path(recipe_path) if recipe_path else None, settings.keymap,
                settings.translate).run()
