"""Kitchen validators for the tests that need one: one embedded kitchen per primitive set for a whole test
module, with HOME and the kitchen's script cache in a temp dir; `checked` stops them and asserts that no
kitchen process is left behind. Import the fixtures into a test module to use them."""

from __future__ import annotations

import pytest

from cook2ltl.execution.kitchen_check import KitchenValidator
from cook2ltl.reduce.primitives import load_primitives


@pytest.fixture(scope="module")
def validators(tmp_path_factory):
    """validators("recipe") → a KitchenValidator for that set, started once per module."""
    pytest.importorskip("ai2thor")
    home = tmp_path_factory.mktemp("home")
    made: dict[str, KitchenValidator] = {}
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("HOME", str(home))
        mp.setenv("COOK2LTL_KITCHEN_CACHE", str(home / "cache"))
        mp.delenv("COOK2LTL_THOR_EXECUTABLE", raising=False)
        mp.delenv("COOK2LTL_THOR_PLATFORM", raising=False)
        yield lambda name: made.setdefault(name, KitchenValidator(load_primitives(name)))
        for validator in made.values():
            player = validator._controller.server.unity_proc if validator._controller else None
            validator.close()
            assert player is None or player.poll() is not None  # no kitchen process left behind
