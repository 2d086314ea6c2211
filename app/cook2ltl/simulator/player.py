"""The embedded kitchen's executable: what ai2thor's Controller launches in place
of a Unity build (``python -m cook2ltl.simulator.player``, through the wrapper
script that `launcher.embedded_executable` writes).

The Controller passes the two FIFO paths in the environment, creates both
pipes, and first opens the server pipe for reading. So the player opens the
server pipe for writing, sends the first event, then opens the client pipe to
read actions, answering each one, until the Controller closes its end.
"""

from __future__ import annotations

import os
import sys
import threading
import time
import traceback

from cook2ltl.simulator import protocol
from cook2ltl.simulator.session import Session

SERVER_PIPE = "AI2THOR_FIFO_SERVER_PIPE_PATH"  # player -> Controller
CLIENT_PIPE = "AI2THOR_FIFO_CLIENT_PIPE_PATH"  # Controller -> player


def screen_size(argv: list[str]) -> tuple[int, int]:
    """Width and height from Unity-style flags (-screen-width 300 -screen-height 300)."""
    size = {"-screen-width": 300, "-screen-height": 300}
    for flag, value in zip(argv, argv[1:], strict=False):
        if flag in size and value.isdigit() and int(value) > 0:
            size[flag] = int(value)
    return size["-screen-width"], size["-screen-height"]


def serve(session: Session, server_pipe: str, client_pipe: str) -> None:
    with open(server_pipe, "wb") as out:
        protocol.write_metadata(out, session.first_event())
        with open(client_pipe, "rb") as inbox:
            while (action := protocol.read_action(inbox)) is not None:
                protocol.write_metadata(out, _answer(session, action))


def _answer(session: Session, action: dict) -> dict:
    try:
        return session.handle(action)
    except Exception as err:  # a kitchen bug must not kill the player: report a failed action
        traceback.print_exc(file=sys.stderr)
        return session.failure(action, f"internal kitchen error: {type(err).__name__}: {err}")


def exit_with_parent(parent: int, every: float = 0.5) -> None:
    """End the player once the Controller's process is gone: a FIFO open() would otherwise wait forever."""
    while os.getppid() == parent:
        time.sleep(every)
    os._exit(0)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    server_pipe, client_pipe = os.environ.get(SERVER_PIPE), os.environ.get(CLIENT_PIPE)
    if not server_pipe or not client_pipe:
        print(
            f"cook2ltl kitchen player: {SERVER_PIPE} and {CLIENT_PIPE} are not set; "
            "it is meant to be started by ai2thor's Controller (see cook2ltl.execution.launcher).",
            file=sys.stderr,
        )
        return 2
    server_type = os.environ.get("AI2THOR_SERVER_TYPE", "FIFO")
    if server_type != "FIFO":
        print(f"cook2ltl kitchen player: only the FIFO server is supported, not {server_type!r}", file=sys.stderr)
        return 2
    width, height = screen_size(argv)
    threading.Thread(target=exit_with_parent, args=(os.getppid(),), daemon=True).start()
    try:
        serve(Session(width=width, height=height), server_pipe, client_pipe)
    except BrokenPipeError:
        pass  # the Controller went away mid-answer; nothing left to do
    return 0


if __name__ == "__main__":
    sys.exit(main())
