"""FIFO framing and the THOR event envelope, without starting a process."""

import io
import json
import os
import struct
import subprocess
import sys
import textwrap
import time

import msgpack
import pytest

from cook2ltl.simulator import protocol, rules
from cook2ltl.simulator.player import _answer, screen_size
from cook2ltl.simulator.session import Session


def action_bytes(action: dict) -> bytes:
    # What ai2thor's FifoServer._send_message writes.
    body = json.dumps(action).encode()
    return struct.pack("!BI", 2, len(body)) + body + struct.pack("!BI", 255, 0)


def test_reads_actions_as_the_controller_frames_them():
    stream = io.BytesIO(action_bytes({"action": "Pass", "sequenceId": 3}) + action_bytes({"action": "Done"}))
    assert protocol.read_action(stream) == {"action": "Pass", "sequenceId": 3}
    assert protocol.read_action(stream) == {"action": "Done"}
    assert protocol.read_action(stream) is None  # the Controller closed its end


def test_a_cut_message_is_a_protocol_error():
    whole = action_bytes({"action": "Pass"})
    with pytest.raises(protocol.ProtocolError):
        protocol.read_action(io.BytesIO(whole[:-5]))
    with pytest.raises(protocol.ProtocolError):
        protocol.read_action(io.BytesIO(whole[:8]))


def test_metadata_is_one_msgpack_field_then_end_of_message():
    out = io.BytesIO()
    protocol.write_metadata(out, {"sequenceId": 1})
    data = out.getvalue()
    kind, length = struct.unpack("!BI", data[:5])
    assert kind == 1
    assert msgpack.unpackb(data[5 : 5 + length]) == {"sequenceId": 1}
    assert data[5 + length :] == struct.pack("!BI", 255, 0)


def test_screen_size_comes_from_unity_flags():
    assert screen_size(["-screen-fullscreen", "0", "-screen-width", "64", "-screen-height", "48"]) == (64, 48)
    assert screen_size([]) == (300, 300)


def test_the_session_answers_in_thor_shape():
    session = Session()
    first = session.first_event()
    assert first["sequenceId"] == 0 and first["agents"][0]["objects"] == []
    event = session.handle({"action": "Reset", "sceneName": "FloorPlan3_physics", "sequenceId": 0})
    agent = event["agents"][0]
    assert agent["sceneName"] == "FloorPlan3_physics" and agent["lastActionSuccess"]
    for key in ("lastAction", "errorMessage", "errorCode", "actionReturn", "screenWidth", "thirdPartyCameras"):
        assert key in agent
    obj = agent["objects"][0]
    for key in ("objectId", "objectType", "visible", "isOpen", "isToggled", "temperature", "parentReceptacles"):
        assert key in obj
    init = session.handle({"action": "Initialize", "sequenceId": 1})["agents"][0]
    assert init["actionReturn"] == {"cameraNearPlane": 0.1, "cameraFarPlane": 20.0}


def test_the_session_refuses_actions_before_a_scene_and_unknown_scenes():
    session = Session()
    agent = session.handle({"action": "PickupObject", "objectId": "x", "sequenceId": 1})["agents"][0]
    assert not agent["lastActionSuccess"] and "no scene is loaded" in agent["errorMessage"]
    agent = session.handle({"action": "Reset", "sceneName": "FloorPlan99", "sequenceId": 2})["agents"][0]
    assert not agent["lastActionSuccess"] and agent["errorCode"] == "InvalidArgument"


def test_the_session_reports_internal_errors_as_failed_actions():
    session = Session()
    session.handle({"action": "Reset", "sceneName": "FloorPlan1", "sequenceId": 0})
    agent = session.failure({"action": "PickupObject", "sequenceId": 4}, "internal kitchen error: boom")["agents"][0]
    assert agent["sequenceId"] == 4 and not agent["lastActionSuccess"]
    assert agent["errorMessage"] == "internal kitchen error: boom"


def test_the_session_keeps_working_after_a_held_egg_is_not_broken():
    session = Session()
    session.handle({"action": "Reset", "sceneName": "FloorPlan1", "sequenceId": 0})
    egg = _first(session, "Egg")
    session.handle({"action": "PickupObject", "objectId": egg, "forceAction": True, "sequenceId": 1})
    agent = session.handle({"action": "BreakObject", "objectId": egg, "sequenceId": 2})["agents"][0]
    assert not agent["lastActionSuccess"] and "down before breaking it" in agent["errorMessage"]
    assert agent["inventoryObjects"] == [{"objectId": egg, "objectType": "Egg"}]
    agent = session.handle({"action": "DropHandObject", "sequenceId": 3})["agents"][0]
    assert agent["lastActionSuccess"] and agent["inventoryObjects"] == []


def test_a_rule_that_loses_the_held_object_fails_the_action_not_the_player(monkeypatch):
    def vanish(state, action):  # a kitchen bug: removes what the agent holds
        return state.evolve(objects=state.with_things(removed=(state.held,))), None

    monkeypatch.setitem(rules.HANDLERS, "BreakObject", vanish)
    session = Session()
    session.handle({"action": "Reset", "sceneName": "FloorPlan1", "sequenceId": 0})
    session.handle({"action": "PickupObject", "objectId": _first(session, "Apple"), "sequenceId": 1})
    agent = _answer(session, {"action": "BreakObject", "objectId": "x", "sequenceId": 2})["agents"][0]
    assert not agent["lastActionSuccess"] and "internal kitchen error" in agent["errorMessage"]
    assert _answer(session, {"action": "DropHandObject", "sequenceId": 3})["agents"][0]["lastActionSuccess"]


def _first(session: Session, object_type: str) -> str:
    return next(o for o, t in session.state.objects.items() if t.object_type == object_type)


def test_the_player_ends_when_its_controller_dies(tmp_path):
    # A parent that starts the player on pipes nobody opens, then dies: the
    # player, blocked in open(), must not outlive it.
    for name in ("server.pipe", "client.pipe"):
        os.mkfifo(tmp_path / name)
    pid_file = tmp_path / "player.pid"
    parent = textwrap.dedent(
        f"""
        import os, subprocess, sys, time
        env = dict(os.environ, AI2THOR_FIFO_SERVER_PIPE_PATH={str(tmp_path / "server.pipe")!r},
                   AI2THOR_FIFO_CLIENT_PIPE_PATH={str(tmp_path / "client.pipe")!r})
        player = subprocess.Popen([sys.executable, "-m", "cook2ltl.simulator.player"], env=env)
        open({str(pid_file)!r}, "w").write(str(player.pid))
        time.sleep(2)  # let the player start and block before its parent goes
        """
    )
    subprocess.run([sys.executable, "-c", parent], check=True, timeout=30)
    pid = int(pid_file.read_text())
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline and _alive(pid):
        time.sleep(0.1)
    assert not _alive(pid)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return True
