"""Finding and starting a kitchen: the hang guard, and "THOR unavailable: <reason>"
instead of a hang when a real build is missing, broken or silent."""

import os
import threading
import time

import pytest

pytest.importorskip("ai2thor")

from cook2ltl.execution.launcher import (  # noqa: E402
    KitchenUnavailable,
    ThorBuild,
    find_thor_build,
    start_kitchen,
    start_thor,
)
from cook2ltl.simulator.scenes import UnknownScene  # noqa: E402

COMMIT = "f0825767cd50d69f666c7f282e54abfe58f1e917"


@pytest.fixture
def home(thor_home, tmp_path, monkeypatch):
    """A HOME of this test's own, so staged releases do not leak between tests."""
    path = tmp_path / "home"
    path.mkdir()
    monkeypatch.setenv("HOME", str(path))
    return path


@pytest.fixture
def fake_player(tmp_path, home):
    """Write a shell script standing in for a THOR player; it records its pid."""

    def write(body: str):
        path = tmp_path / "thor-CloudRendering-fake"
        pid_file = tmp_path / "player.pid"
        path.write_text(f'#!/bin/sh\necho $$ > "{pid_file}"\n{body}\n')
        path.chmod(0o755)
        return ThorBuild(platform="CloudRendering", executable=path), pid_file

    return write


def assert_gone(pid_file):
    pid = int(pid_file.read_text())
    with pytest.raises(ProcessLookupError):
        os.kill(pid, 0)  # killed and reaped, not a zombie
    assert not [t for t in threading.enumerate() if t.name == "thor-start"]


def test_a_player_that_never_opens_its_pipes_times_out(fake_player):
    build, pid_file = fake_player("exec sleep 30")
    start = time.monotonic()
    with pytest.raises(KitchenUnavailable, match=r"^THOR unavailable: .* did not answer within 1s"):
        start_thor(build=build, start_timeout=1.0)
    assert time.monotonic() - start < 8
    assert_gone(pid_file)


def test_a_player_that_opens_the_pipe_but_stays_silent_times_out(fake_player):
    build, pid_file = fake_player('exec 3>"$AI2THOR_FIFO_SERVER_PIPE_PATH"\nexec sleep 30')
    with pytest.raises(KitchenUnavailable, match="did not answer within 1s"):
        start_thor(build=build, start_timeout=1.0)
    assert_gone(pid_file)


def test_a_player_that_dies_at_once_is_reported_at_once(fake_player):
    build, pid_file = fake_player("exit 3")
    start = time.monotonic()
    with pytest.raises(KitchenUnavailable, match="exited with code 3 before answering"):
        start_thor(build=build, start_timeout=60.0)
    assert time.monotonic() - start < 8
    assert_gone(pid_file)


def test_no_build_installed(home):
    with pytest.raises(KitchenUnavailable, match="no AI2-THOR build installed: set COOK2LTL_THOR_EXECUTABLE"):
        find_thor_build()


def test_an_explicit_path_must_be_an_executable(home, tmp_path, monkeypatch):
    monkeypatch.setenv("COOK2LTL_THOR_EXECUTABLE", str(tmp_path / "missing"))
    with pytest.raises(KitchenUnavailable, match="is not an executable file"):
        find_thor_build()


def stage_release(home, platform: str):
    folder = home / ".ai2thor" / "releases" / f"thor-{platform}-{COMMIT}"
    folder.mkdir(parents=True, exist_ok=True)
    binary = folder / folder.name
    binary.write_text("#!/bin/sh\nexit 3\n")
    binary.chmod(0o755)
    (folder / "metadata.json").write_text('{"server_types": ["FIFO"]}')
    return folder


def test_a_staged_release_is_found(home):
    stage_release(home, "CloudRendering")
    assert find_thor_build() == ThorBuild(platform="CloudRendering", commit_id=COMMIT)


def test_a_linux64_release_without_a_display_is_unavailable(home, monkeypatch):
    monkeypatch.delenv("DISPLAY", raising=False)
    build = ThorBuild(platform="Linux64", commit_id=COMMIT)
    with pytest.raises(KitchenUnavailable, match="needs an X display"):
        start_thor(build=build, start_timeout=5.0)


def test_a_staged_release_that_cannot_run_is_unavailable(home):
    # Without Vulkan the Controller refuses CloudRendering; with it, the stand-in exits.
    stage_release(home, "CloudRendering")
    build = ThorBuild(platform="CloudRendering", commit_id=COMMIT)
    with pytest.raises(KitchenUnavailable, match="^THOR unavailable: "):
        start_thor(build=build, start_timeout=5.0)


def test_auto_falls_back_to_the_embedded_kitchen(home):
    controller = start_kitchen("FloorPlan3", backend="auto", width=64, height=64)
    try:
        assert controller.last_event.metadata["sceneName"] == "FloorPlan3_physics"
    finally:
        controller.stop()


def test_arguments_are_checked_before_anything_starts(home):
    with pytest.raises(UnknownScene):
        start_kitchen("FloorPlan999", backend="embedded")
    with pytest.raises(ValueError, match="backend must be"):
        start_kitchen("FloorPlan1", backend="unity")
    with pytest.raises(ValueError, match="embedded-only"):
        start_thor(build=ThorBuild(platform="CloudRendering"), slice_needs_knife=False)


def test_the_configured_executable_and_its_platform(home, tmp_path, monkeypatch):
    binary = tmp_path / "thor-Linux64-local"
    binary.write_text("#!/bin/sh\n")
    binary.chmod(0o755)
    monkeypatch.setenv("COOK2LTL_THOR_EXECUTABLE", str(binary))
    assert find_thor_build() == ThorBuild(platform="Linux64", executable=binary)
    monkeypatch.setenv("COOK2LTL_THOR_PLATFORM", "WebGL")
    with pytest.raises(KitchenUnavailable, match="use one of Linux64, CloudRendering"):
        find_thor_build()
