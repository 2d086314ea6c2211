"""Integration tests run the real provisioned models; `make test` provisions them first."""

import pytest

from cook2ltl.assembly.manifest import ModelState, load_manifest, state_of


def require_models(*names: str) -> None:
    manifest = load_manifest()
    missing = [name for name in names if state_of(manifest[name], verify_hash=False) != ModelState.READY]
    if missing:
        pytest.fail(f"models not provisioned: {', '.join(missing)}; run `make models`")
