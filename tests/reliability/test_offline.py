"""The offline guarantee: the test run's socket guard, the variables every entry point sets, and subprocesses."""

import os
import socket
import subprocess
import sys
import threading

import pytest

from cook2ltl import offline

VARIABLES = tuple(offline.OFFLINE_VARIABLES)


@pytest.fixture
def refused():
    """The hosts this test was refused; cleared after, as these refusals are the point of the test."""
    yield offline.blocked_hosts
    offline.blocked_hosts.clear()


@pytest.mark.parametrize("host", ["huggingface.co", "8.8.8.8", "2001:4860:4860::8888"])
def test_a_connection_beyond_this_machine_fails_naming_the_host(refused, host):
    with pytest.raises(offline.NetworkBlocked, match=f"connection to {host}"):
        socket.create_connection((host, 443), timeout=1)
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    with socket.socket(family, socket.SOCK_STREAM) as sock:
        with pytest.raises(offline.NetworkBlocked):
            sock.connect((host, 443))
        with pytest.raises(offline.NetworkBlocked):
            sock.connect_ex((host, 443))
    assert host in refused


def test_name_lookups_beyond_this_machine_fail(refused):
    with pytest.raises(offline.NetworkBlocked, match="pypi.org"):
        socket.getaddrinfo("pypi.org", 443)
    assert refused == ["pypi.org"]


def greeting_server() -> int:
    server = socket.create_server(("127.0.0.1", 0))
    threading.Thread(target=lambda: server.accept()[0].sendall(b"hi"), daemon=True).start()
    return server.getsockname()[1]


def test_loopback_and_unix_sockets_still_work(tmp_path):
    for host in ("127.0.0.1", "localhost"):
        with socket.create_connection((host, greeting_server()), timeout=5) as client:
            assert client.recv(2) == b"hi"
    path = str(tmp_path / "s")
    unix = socket.socket(socket.AF_UNIX)
    unix.bind(path)
    unix.listen()
    with socket.socket(socket.AF_UNIX) as client:
        client.connect(path)
    unix.close()


def run_python(code: str, **env_changes) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in VARIABLES}  # as a user's shell would be
    env.update(env_changes)
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)


def test_cook2ltl_subprocesses_of_the_test_run_are_guarded_too():
    assert os.environ[offline.NO_NETWORK_ENV] == "1"  # set by tests/conftest.py for every child
    code = ("from cook2ltl import offline; offline.enforce()\n"
            "import socket\n"
            "try:\n    socket.create_connection(('example.org', 80), timeout=1)\n"
            "except offline.NetworkBlocked as e:\n    print('blocked', e)\n")
    result = run_python(code)
    assert "blocked cook2ltl is offline: refused a network connection to example.org" in result.stdout


PRINT_VARIABLES = f"import os; print([os.environ.get(v) for v in {VARIABLES!r}])"


def test_the_cli_and_python_m_cook2ltl_set_the_offline_variables_first():
    through_main = run_python(
        "import runpy, sys\nsys.argv = ['cook2ltl', 'ltl', 'parse', 'F a']\n"
        "try:\n    runpy.run_module('cook2ltl', run_name='__main__')\nexcept SystemExit:\n    pass\n"
        + PRINT_VARIABLES)
    assert through_main.stdout.strip().endswith("['1', '1', '1']"), through_main.stderr
    before = run_python(PRINT_VARIABLES)
    assert before.stdout.strip() == "[None, None, None]"  # so the line above proves cook2ltl set them


def test_a_backend_sets_them_before_it_imports_its_library():
    from cook2ltl.reduce.llm import LlamaModel

    assert "enforce()" in open(sys.modules[LlamaModel.__module__].__file__).read()
    result = run_python(
        "from pathlib import Path\nfrom cook2ltl.parse.gliner_spans import load_gliner\n"
        "try:\n    load_gliner(Path('/nonexistent'))\nexcept Exception:\n    pass\n" + PRINT_VARIABLES)
    assert result.stdout.strip() == "['1', '1', '1']"


def test_the_textual_app_sets_the_offline_variables_before_it_starts():
    result = run_python(
        "import runpy, sys\nimport textual.app\ntextual.app.App.run = lambda self, *a, **k: None\n"
        "sys.argv = ['cook2ltl.ui']\nrunpy.run_module('cook2ltl.ui', run_name='__main__')\n" + PRINT_VARIABLES)
    assert result.stdout.strip() == "['1', '1', '1']", result.stderr


def test_the_embedded_kitchen_player_is_guarded_too():
    result = run_python(
        "import socket\nfrom cook2ltl.execution import launcher\nfrom cook2ltl.simulator import player\n"
        "player.main = lambda: socket.create_connection(('example.org', 80), timeout=1)\n"
        "launcher.run_player()\n")
    assert "refused a network connection to example.org" in result.stderr and result.returncode != 0


def test_cook2ltl_app_sets_the_offline_variables_before_the_app_starts():
    result = run_python(
        "import runpy, sys\nimport textual.app\ntextual.app.App.run = lambda self, *a, **k: None\n"
        "sys.argv = ['cook2ltl', 'app']\n"
        "try:\n    runpy.run_module('cook2ltl', run_name='__main__')\nexcept SystemExit:\n    pass\n"
        + PRINT_VARIABLES)
    assert result.stdout.strip().endswith("['1', '1', '1']"), result.stderr
