"""The command palette's main actions: going to a screen, help, and the actions of the screen in front."""

from __future__ import annotations

from functools import partial

from textual.command import DiscoveryHit, Hit, Hits, Provider

APP_COMMANDS = (
    ("Go to Translate", "Recipe editor, spans, frames, reductions and formulas", "app.switch_mode('translate')"),
    ("Go to Library", "Review the action library", "app.switch_mode('library')"),
    ("Go to Rollout", "Run a task or formula in the kitchen", "app.switch_mode('rollout')"),
    ("Help", "What each screen does, and the keys", "app.help"),
)
CANCEL = ("Cancel the running work", "Stop after the current step", "cancel")


class MainCommands(Provider):
    def _commands(self) -> list[tuple[str, str, str]]:
        screen = self.screen
        commands = list(getattr(screen, "PALETTE", ()))
        if getattr(screen, "busy", False):
            commands.append(CANCEL)
        return commands + list(APP_COMMANDS)

    async def discover(self) -> Hits:
        for title, help_text, action in self._commands():
            yield DiscoveryHit(title, partial(self.screen.run_action, action), help=help_text)

    async def search(self, query: str) -> Hits:
        matcher = self.matcher(query)
        for title, help_text, action in self._commands():
            score = matcher.match(title)
            if score > 0:
                yield Hit(score, matcher.highlight(title), partial(self.screen.run_action, action), help=help_text)
