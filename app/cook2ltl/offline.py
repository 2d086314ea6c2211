"""Nothing reaches the network: model libraries are told to stay off their hubs, and (for tests, or when
COOK2LTL_NO_NETWORK=1) any connection beyond loopback and Unix sockets fails, naming the host.

`enforce()` runs first on every entry point: the CLI's `main` (also `python -m cook2ltl`), the app, and each
heavy backend before it imports its library.
"""

from __future__ import annotations

import ipaddress
import os
import socket
import sys

OFFLINE_VARIABLES = {"HF_HUB_OFFLINE": "1", "TRANSFORMERS_OFFLINE": "1", "HF_DATASETS_OFFLINE": "1"}
# Their own progress bars and advice would garble our rich output.
QUIET_VARIABLES = {"TRANSFORMERS_VERBOSITY": "error", "HF_HUB_DISABLE_PROGRESS_BARS": "1", "TQDM_DISABLE": "1"}
NO_NETWORK_ENV = "COOK2LTL_NO_NETWORK"  # "1": refuse every non-local connection (tests set it for subprocesses)
LOCAL_NAMES = {"localhost", "localhost.localdomain", "ip6-localhost", "ip6-loopback"}

as_given: dict[str, str | None] = {}  # the user's own values of OFFLINE_VARIABLES, before enforce() set them
blocked_hosts: list[str] = []  # every refused host, so a test fails even if a library swallowed the error


class NetworkBlocked(ConnectionError):
    """A connection beyond this machine was attempted while the network is forbidden."""


def enforce() -> None:
    for name, value in OFFLINE_VARIABLES.items():
        as_given.setdefault(name, os.environ.get(name))
        os.environ[name] = value
    for name, value in QUIET_VARIABLES.items():
        os.environ.setdefault(name, value)
    # llama.cpp's OpenMP threads wait between the steps of every token: a short spin then sleep. Sleeping at once
    # (OMP_WAIT_POLICY=passive) made decoding 25 % slower; spinning long holds a core other work needs.
    os.environ.setdefault("GOMP_SPINCOUNT", "10000")
    if os.environ.get(NO_NETWORK_ENV) == "1":
        forbid_network()


def is_local(host: object) -> bool:
    """Loopback names and addresses; None / "" are the local wildcard."""
    if host is None or host == "" or host == b"":
        return True
    name = host.decode() if isinstance(host, bytes) else str(host)
    if name.lower() in LOCAL_NAMES:
        return True
    try:
        return ipaddress.ip_address(name.split("%")[0]).is_loopback
    except ValueError:
        return False


def forbid_network() -> None:
    """Patch the socket module so only loopback and AF_UNIX connect; idempotent."""
    if getattr(socket.socket.connect, "_cook2ltl_guard", False):
        return
    original_connect, original_connect_ex = socket.socket.connect, socket.socket.connect_ex
    original_getaddrinfo = socket.getaddrinfo

    def connect(sock, address, *rest):
        _check_address(sock, address)
        return original_connect(sock, address, *rest)

    def connect_ex(sock, address, *rest):
        _check_address(sock, address)
        return original_connect_ex(sock, address, *rest)

    def getaddrinfo(host, *args, **kwargs):
        if not is_local(host):
            _refuse(host)
        return original_getaddrinfo(host, *args, **kwargs)

    for guard in (connect, connect_ex, getaddrinfo):
        guard._cook2ltl_guard = True
    socket.socket.connect, socket.socket.connect_ex, socket.getaddrinfo = connect, connect_ex, getaddrinfo


def _check_address(sock: socket.socket, address) -> None:
    if sock.family == getattr(socket, "AF_UNIX", None):
        return
    host = address[0] if isinstance(address, tuple) and address else address
    if not is_local(host):
        _refuse(host)


def _refuse(host: object) -> None:
    from cook2ltl.text_safety import visible  # rare: rich (text_safety) loads only when a connection is refused

    name = visible(host.decode(errors="replace") if isinstance(host, bytes) else str(host))  # a host name is text
    blocked_hosts.append(name)
    message = f"cook2ltl is offline: refused a network connection to {name}"
    print(message, file=sys.stderr)  # seen even when a library swallows the error
    raise NetworkBlocked(message)
