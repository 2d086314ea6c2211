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
