"""The ai2thor Controller every kitchen runs under, with a kitchen that dies mid-run reported as what it is.

ai2thor lets a dead player surface as BrokenPipeError (or a timeout) from whichever call touches its pipes next,
and its own stop() fails the same way, leaving a pipe open and the build locked. Imported only by the launcher,
when a kitchen starts, so ai2thor stays a lazy import."""

from __future__ import annotations

from typing import Any

from ai2thor.controller import Controller

from cook2ltl.execution.unavailable import KitchenUnavailable


class KitchenController(Controller):
    def reset(self, scene=None, **init_params: Any):
        try:
            return super().reset(scene, **init_params)
        except (OSError, RuntimeError) as err:  # TimeoutError and BrokenPipeError are OSErrors
            raise KitchenUnavailable(f"the kitchen stopped answering during reset to {scene}: {err}") from err

    def step(self, action: Any = None, **action_args: Any):
        try:
            return super().step(action, **action_args)
        except (OSError, RuntimeError) as err:
            name = action.get("action") if isinstance(action, dict) else action
            raise KitchenUnavailable(f"the kitchen stopped answering during {name}: {err}") from err

    def stop(self) -> None:
        """Stop the player and release everything, whether or not it is still alive; never raises."""
        try:
            super().stop()
        except OSError:  # flushing a pipe to a dead player: finish what ai2thor's stop skipped
            self._release_after_death()

    def _release_after_death(self) -> None:
        server = self.server
        for pipe in (server.client_pipe, server.server_pipe):
            if pipe is not None:
                try:
                    pipe.close()
                except OSError:
                    pass  # closed all the same: a failed flush still closes the file
        if server.unity_proc is not None and server.unity_proc.poll() is None:
            server.unity_proc.kill()
            server.unity_proc.wait(5)
        self._build.unlock()
