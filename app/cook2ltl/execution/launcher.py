"""Start an unmodified `ai2thor.controller.Controller` on the embedded kitchen or
on a real AI2-THOR build, under a hard start-up timeout.

The Controller blocks forever if its player dies before opening the FIFO pipes
(it waits in `open()` on the server pipe). So it is built with
`download_only=True`, which launches nothing, and then started in a worker
thread that this module watches: if the player exits or stays silent past the
timeout, the player is killed, the pipes are poked so the blocked thread wakes
up and fails, and `KitchenUnavailable("THOR unavailable: <reason>")` is raised.
"""

from __future__ import annotations

import hashlib
import os
import re
import shlex
import sys
import tempfile
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from platformdirs import user_cache_dir

from cook2ltl import offline
from cook2ltl.errors import UserError
from cook2ltl.execution.unavailable import KitchenUnavailable
from cook2ltl.paths import user_path
from cook2ltl.simulator import scenes

THOR_EXECUTABLE_ENV = "COOK2LTL_THOR_EXECUTABLE"  # path to a THOR player binary
THOR_PLATFORM_ENV = "COOK2LTL_THOR_PLATFORM"  # Linux64 or CloudRendering, for that binary
KITCHEN_PARENT_ENV = "COOK2LTL_KITCHEN_PARENT"  # the pid that launched the embedded kitchen; it ends with it
PLATFORMS = ("Linux64", "CloudRendering")
_RELEASE = re.compile(r"^thor-(Linux64|CloudRendering)-([0-9a-f]{40})$")
_POISON = bytes([2, 0, 0, 0, 0])  # an ACTION header: a field the Controller never accepts, so it fails at once


@dataclass(frozen=True)
class ThorBuild:
    """A real AI2-THOR player: an explicit binary, or a release staged in ~/.ai2thor/releases."""

    platform: str
    executable: Path | None = None  # set for an explicit binary
    commit_id: str | None = None  # set for a staged release


def start_kitchen(
    scene: str = "FloorPlan1",
    backend: str = "auto",
    *,
    thor_executable: str | os.PathLike | None = None,
    **options: Any,
):
    """A started Controller. backend: "embedded", "thor", or "auto" (a real THOR
    build if one is given, configured or staged, else the embedded kitchen)."""
    if backend == "embedded":
        return start_embedded(scene, **options)
    if backend == "thor":
        return start_thor(scene, executable=thor_executable, **options)
    if backend != "auto":
        raise ValueError(f"backend must be 'embedded', 'thor' or 'auto', not {backend!r}")
    try:
        build = find_thor_build(thor_executable)
    except KitchenUnavailable:
        return start_embedded(scene, **options)
    return start_thor(scene, build=build, **options)


def start_embedded(
    scene: str = "FloorPlan1",
    *,
    width: int = 300,
    height: int = 300,
    start_timeout: float = 30.0,
    step_timeout: float = 10.0,
    slice_needs_knife: bool = True,
    **init_params: Any,
):
    """A Controller driving the embedded kitchen (no Unity, no display needed)."""
    scenes.canonical_scene(scene)  # fail fast on a name the kitchen does not have
    # The Controller copies os.environ into the player's environment: this is how the player learns who
    # launched it, even if that process is killed before the player has started (see run_player).
    os.environ[KITCHEN_PARENT_ENV] = str(os.getpid())
    Controller = _controller_class()
    controller = Controller(
        local_executable_path=str(embedded_executable()),
        download_only=True,
        width=width,
        height=height,
        # The Controller needs some display for a local executable; the kitchen ignores it.
        x_display=os.environ.get("DISPLAY") or ":0",
        server_timeout=step_timeout,
        server_start_timeout=_inner_timeout(start_timeout),
    )
    init_params["sliceNeedsKnife"] = slice_needs_knife
    return _start_guarded(controller, scene, init_params, start_timeout, "the embedded kitchen")


def start_thor(
    scene: str = "FloorPlan1",
    *,
    build: ThorBuild | None = None,
    executable: str | os.PathLike | None = None,
    x_display: str | None = None,
    width: int = 300,
    height: int = 300,
    start_timeout: float = 120.0,
    step_timeout: float = 100.0,
    slice_needs_knife: bool = True,
    **init_params: Any,
):
    """A Controller driving a real AI2-THOR build (`build`, else `find_thor_build(executable)`);
    KitchenUnavailable if there is none that runs."""
    if not slice_needs_knife:
        raise ValueError("slice_needs_knife=False is embedded-only: a real THOR build always needs a knife to slice")
    build = build or find_thor_build(executable)
    Controller = _controller_class()
    display = x_display or os.environ.get("DISPLAY")
    if build.platform == "Linux64" and not display:
        raise KitchenUnavailable("the Linux64 build needs an X display (DISPLAY is unset); use a CloudRendering build")
    common = dict(
        download_only=True,
        width=width,
        height=height,
        x_display=display or ":0",  # CloudRendering ignores it; the Controller needs a value
        server_timeout=step_timeout,
        server_start_timeout=_inner_timeout(start_timeout),
    )
    try:
        if build.executable is not None:
            controller = Controller(local_executable_path=str(build.executable), **common)
        else:
            import ai2thor.platform  # heavy: ai2thor loads only when a THOR build starts

            platform = getattr(ai2thor.platform, build.platform)
            controller = Controller(platform=platform, commit_id=build.commit_id, **common)
    except Exception as err:  # the Controller reports missing Vulkan, X, metadata as plain Exceptions
        raise KitchenUnavailable(_first_lines(err)) from err
    return _start_guarded(controller, scene, init_params, start_timeout, f"the {build.platform} THOR build")


def find_thor_build(executable: str | os.PathLike | None = None) -> ThorBuild:
    """The THOR build to use: `executable`, else $COOK2LTL_THOR_EXECUTABLE, else a
    release staged in ~/.ai2thor/releases (the folder the Controller reads)."""
    chosen = executable or os.environ.get(THOR_EXECUTABLE_ENV)
    if chosen:
        try:
            path = user_path(chosen, THOR_EXECUTABLE_ENV)
        except UserError as error:
            raise KitchenUnavailable(error.message) from None
        if not (path.is_file() and os.access(path, os.X_OK)):
            raise KitchenUnavailable(f"{path} is not an executable file (from {THOR_EXECUTABLE_ENV} or settings)")
        guessed = "CloudRendering" if "CloudRendering" in path.name else "Linux64"
        platform = os.environ.get(THOR_PLATFORM_ENV) or guessed
        if platform not in PLATFORMS:
            raise KitchenUnavailable(f"{THOR_PLATFORM_ENV}={platform!r}; use one of {', '.join(PLATFORMS)}")
        return ThorBuild(platform=platform, executable=path)
    return _staged_release(Path.home() / ".ai2thor" / "releases")


def _staged_release(releases: Path) -> ThorBuild:
    found = []
    for folder in releases.iterdir() if releases.is_dir() else ():
        match = _RELEASE.match(folder.name)
        binary = folder / folder.name
        # Without metadata.json the Controller would try to download it.
        if match and binary.is_file() and (folder / "metadata.json").is_file():
            found.append((folder, match.group(1), match.group(2)))
    if not found:
        raise KitchenUnavailable(
            f"no AI2-THOR build installed: set {THOR_EXECUTABLE_ENV} to a THOR player binary, "
            f"or stage a release (thor-<Linux64|CloudRendering>-<commit>/ with metadata.json) in {releases}"
        )
    wanted = _controller_commit()
    preferred = "Linux64" if os.environ.get("DISPLAY") else "CloudRendering"
    _, platform, commit = max(
        found, key=lambda f: (f[2] == wanted, f[1] == preferred, f[0].stat().st_mtime)
    )
    return ThorBuild(platform=platform, commit_id=commit)


def embedded_executable() -> Path:
    """The script the Controller runs as its 'Unity build' (written once, reused).

    The Controller splits the command line with shlex, so the path must not
    contain whitespace; the script re-runs this very interpreter on the player.
    """
    app_dir = Path(__file__).resolve().parents[2]
    script = (
        "#!/bin/sh\n"
        "# Written by cook2ltl.execution.launcher: runs the embedded THOR-compatible kitchen.\n"
        f"PYTHONPATH={shlex.quote(str(app_dir))}${{PYTHONPATH:+:$PYTHONPATH}} "
        f"exec {shlex.quote(sys.executable)} -c 'from cook2ltl.execution.launcher import run_player; run_player()' "
        '"$@"\n'
    )
    folder = _cache_dir()
    path = folder / f"kitchen-player-{hashlib.sha256(script.encode()).hexdigest()[:12]}"
    if not path.is_file():
        folder.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=".kitchen-player-")
        with os.fdopen(fd, "w") as f:
            f.write(script)
        os.chmod(tmp, 0o755)
        os.replace(tmp, path)  # atomic: concurrent launches never see half a script
    return path


def run_player() -> None:
    """The embedded kitchen's entry point: the player, ended as soon as the process that launched it is gone,
    including one killed while the player was still starting (its parent is then already someone else)."""
    # only the kitchen's own process runs the player: msgpack and the simulator never load in the launching one
    from cook2ltl.simulator import player

    offline.enforce()  # the kitchen needs no network; under COOK2LTL_NO_NETWORK=1 it cannot reach one either
    launcher = int(os.environ.get(KITCHEN_PARENT_ENV) or os.getppid())
    threading.Thread(target=player.exit_with_parent, args=(launcher,), daemon=True).start()
    sys.exit(player.main())


def _cache_dir() -> Path:
    cache = os.environ.get("COOK2LTL_KITCHEN_CACHE")
    folder = (user_path(cache, "$COOK2LTL_KITCHEN_CACHE") if cache else Path(user_cache_dir("cook2ltl"))) / "kitchen"
    if any(c.isspace() for c in str(folder)):
        folder = Path(tempfile.gettempdir()) / f"cook2ltl-kitchen-{os.getuid()}"
    return folder


def _start_guarded(controller, scene: str, init_params: dict[str, Any], timeout: float, what: str):
    outcome: dict[str, BaseException] = {}

    def start() -> None:
        try:
            controller.start(width=controller.width, height=controller.height, x_display=controller.x_display)
            # What Controller.__init__ does after start() when download_only is False.
            controller.initialization_parameters = dict(init_params)
            event = controller.reset(scene)
            if event.metadata["actionReturn"]:
                controller.server.set_init_params(event.metadata["actionReturn"])
        except BaseException as err:  # handed to the waiting thread
            outcome["error"] = err

    worker = threading.Thread(target=start, name="thor-start", daemon=True)
    worker.start()
    deadline = time.monotonic() + timeout
    reason = None
    while worker.is_alive() and reason is None:
        worker.join(0.05)
        proc = controller.server.unity_proc if controller.server else None
        if worker.is_alive() and proc is not None and proc.poll() is not None:
            reason = f"{what} exited with code {proc.returncode} before answering (see {_log_path(controller)})"
        elif worker.is_alive() and time.monotonic() > deadline:
            reason = f"{what} did not answer within {timeout:g}s (see {_log_path(controller)})"
    if reason is not None:
        _abandon(controller, worker)
        raise KitchenUnavailable(reason)
    if "error" in outcome:
        _stop_quietly(controller)
        error = outcome["error"]
        reason = error.reason if isinstance(error, KitchenUnavailable) else _first_lines(error)
        raise KitchenUnavailable(f"{what} failed to start: {reason}") from error
    return controller


def _abandon(controller, worker: threading.Thread) -> None:
    """Kill the player and wake the worker thread wherever it blocks on a pipe."""
    server = controller.server
    proc = server.unity_proc if server else None
    if proc is not None and proc.poll() is None:
        proc.kill()
        proc.wait(5)
    give_up = time.monotonic() + 5
    while server is not None and worker.is_alive() and time.monotonic() < give_up:
        _poke(server.server_pipe_path, os.O_WRONLY, _POISON)
        _poke(server.client_pipe_path, os.O_RDONLY, b"")
        worker.join(0.05)
    _stop_quietly(controller)


def _poke(pipe: str, mode: int, payload: bytes) -> None:
    # Opening the other end releases a blocked open(); the poison ends a blocked read.
    try:
        fd = os.open(pipe, mode | os.O_NONBLOCK)
    except OSError:
        return  # nobody is waiting on this pipe (yet)
    try:
        if payload:
            os.write(fd, payload)
    except OSError:
        pass
    finally:
        os.close(fd)


def _stop_quietly(controller) -> None:
    try:
        controller.stop()
    except Exception:
        pass  # the pipes may already be broken; the player is dead either way


def _inner_timeout(start_timeout: float) -> float:
    # The Controller's own read timeout only backs up the guard, which fires first and says why.
    return start_timeout + 10.0


def _log_path(controller) -> str:
    return os.path.join(controller.log_dir, "unity.log")


def _first_lines(err: BaseException, limit: int = 3) -> str:
    lines = [line.strip() for line in str(err).strip().splitlines() if line.strip()]
    return " ".join(lines[:limit]) or type(err).__name__


def _controller_class():
    try:
        from cook2ltl.execution.controller import KitchenController  # heavy, optional: it imports ai2thor
    except ImportError as err:
        raise KitchenUnavailable(f"the ai2thor package is not installed ({err}); pip install ai2thor") from err
    return KitchenController


def _controller_commit() -> str | None:
    try:
        from ai2thor.build import COMMIT_ID  # heavy, optional: ai2thor loads only when a THOR build is looked for
    except ImportError:
        return None
    return COMMIT_ID
