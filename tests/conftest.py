import os
import sys
from pathlib import Path

import pytest

# `tests.fakes` is importable however pytest is started.
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from cook2ltl import offline  # noqa: E402

# The whole run is offline: connections beyond loopback / AF_UNIX fail naming the host, here and in every
# cook2ltl subprocess and embedded kitchen (their entry points call offline.enforce, which honours the
# variable). Other programs a test starts (MONA for the LTL oracles) are not guarded.
os.environ[offline.NO_NETWORK_ENV] = "1"
offline.forbid_network()


@pytest.fixture(autouse=True)
def _no_network_attempts():
    offline.blocked_hosts.clear()
    yield
    assert not offline.blocked_hosts, f"network connections attempted: {', '.join(offline.blocked_hosts)}"


@pytest.fixture(scope="module")
def thor_home(tmp_path_factory):
    """HOME, the kitchen's script cache and THOR settings confined to a temp dir for a whole module."""
    home = tmp_path_factory.mktemp("home")
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("HOME", str(home))
        mp.setenv("COOK2LTL_KITCHEN_CACHE", str(home / "cache"))
        mp.delenv("COOK2LTL_THOR_EXECUTABLE", raising=False)
        mp.delenv("COOK2LTL_THOR_PLATFORM", raising=False)
        yield home
