"""No kitchen process outlives what started it: a finished rollout, one cut short by Ctrl-C, one killed with
SIGKILL, and a player that dies under a running Controller."""

import os
import signal
import subprocess
import sys
import threading
import time

import pytest

from cook2ltl.assembly.trial import TrialDone, reference_formula, run_trial
from cook2ltl.errors import UserError
from cook2ltl.execution.launcher import start_embedded
from cook2ltl.execution.tasks import find_task
from cook2ltl.execution.unavailable import KitchenUnavailable
from tests.reliability.processes import adopting_orphans, children, command_line, wait_until_gone

pytest.importorskip("ai2thor")
PLAYER = "cook2ltl.execution.launcher"  # the embedded player: `python -c "from cook2ltl.execution.launcher import run_player …"`


@pytest.fixture
def kitchen_home(tmp_path, monkeypatch):
    monkeypatch.setenv("HOME", str(tmp_path))
    monkeypatch.setenv("COOK2LTL_KITCHEN_CACHE", str(tmp_path / "cache"))
    monkeypatch.delenv("COOK2LTL_THOR_EXECUTABLE", raising=False)
    return tmp_path


def rollout(*arguments: str) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "cook2ltl", "rollout", *arguments],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def wait_for_player(run: subprocess.Popen, timeout: float = 120) -> int:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        players = [pid for pid in children(run.pid) if PLAYER in command_line(pid)]
        if players:
            return players[0]
        assert run.poll() is None, f"rollout ended before its kitchen was seen: {run.communicate()}"
        time.sleep(0.05)
    raise AssertionError("no kitchen player started")


def test_a_finished_rollout_leaves_no_process(kitchen_home):
    with adopting_orphans():
        run = rollout("chop-tomato", "--reference", "--json")
        out, err = run.communicate(timeout=300)
        assert run.returncode == 0, err
        assert wait_until_gone(children(os.getpid()), timeout=10) == set()


@pytest.mark.parametrize("signal_number", [signal.SIGINT, signal.SIGTERM, signal.SIGKILL])
def test_a_rollout_stopped_mid_way_leaves_no_process(kitchen_home, signal_number):
    with adopting_orphans():
        run = rollout("refrigerate-apple", "--reference")
        player = wait_for_player(run)
        run.send_signal(signal_number)
        _, err = run.communicate(timeout=60)
        assert "Traceback" not in err or signal_number == signal.SIGINT and "KeyboardInterrupt" not in err
        left = wait_until_gone(children(os.getpid()) | {player}, timeout=10)
        assert left == set(), [command_line(pid) for pid in left]


def test_a_cancelled_rollout_in_process_stops_and_its_kitchen_stops_with_it(kitchen_home):
    task = find_task("refrigerate-apple")
    controller = start_embedded(task.scene)
    player = controller.server.unity_proc
    cancel = threading.Event()
    cancel.set()  # cancelled before its first action: the rollout stops at once, cleanly
    events = list(run_trial(controller, reference_formula(task), task.scene, task, cancel=cancel))
    assert isinstance(events[-1], TrialDone) and events[-1].trial.rollout.stop.value == "cancelled"
    controller.stop()
    assert player.wait(10) is not None


def test_a_player_that_dies_under_a_running_controller_leaves_nothing_behind(kitchen_home):
    controller = start_embedded("FloorPlan1")
    player = controller.server.unity_proc
    player.kill()
    player.wait(10)
    with pytest.raises(KitchenUnavailable, match="stopped answering during Pass"):
        controller.step(action="Pass")
    controller.stop()  # ai2thor's own stop fails on the broken pipe; ours finishes the job quietly
    assert controller.server.client_pipe.closed and controller.server.server_pipe.closed
    assert all(PLAYER not in command_line(pid) for pid in children(os.getpid()))


def test_a_kitchen_that_dies_mid_rollout_is_a_clear_error(kitchen_home):
    task = find_task("refrigerate-apple")
    controller = start_embedded(task.scene)
    controller.server.unity_proc.kill()
    controller.server.unity_proc.wait(10)
    try:
        with pytest.raises(UserError, match="THOR unavailable: the kitchen stopped answering"):
            list(run_trial(controller, reference_formula(task), task.scene, task))
    finally:
        controller.stop()
    assert all(PLAYER not in command_line(pid) for pid in children(os.getpid()))


def test_a_kitchen_that_dies_between_actions_is_a_clear_error(kitchen_home):
    task = find_task("refrigerate-apple")
    controller = start_embedded(task.scene)
    events = run_trial(controller, reference_formula(task), task.scene, task)
    try:
        next(events)  # the kitchen is reset and set up; the first action has run
        controller.server.unity_proc.kill()
        controller.server.unity_proc.wait(10)
        with pytest.raises(UserError, match="THOR unavailable: the kitchen stopped answering"):
            list(events)
    finally:
        controller.stop()
    assert all(PLAYER not in command_line(pid) for pid in children(os.getpid()))
