"""`cook2ltl doctor` names whatever would reach for the network, and says what to change."""

import json

import pytest

from cook2ltl import offline, paths
from cook2ltl.assembly.doctor import network_checks


@pytest.fixture
def clean_env(monkeypatch, tmp_path):
    monkeypatch.setenv("COOK2LTL_MODEL_CACHE", str(paths.model_cache_dir()))  # the real models, whatever HOME is
    monkeypatch.setenv("COOK2LTL_CONFIG", str(tmp_path / "absent.toml"))
    monkeypatch.setenv("HOME", str(tmp_path))  # no staged THOR release
    monkeypatch.setenv("HF_HOME", str(tmp_path / "hf"))
    monkeypatch.delenv("HF_HUB_CACHE", raising=False)
    monkeypatch.delenv("COOK2LTL_THOR_EXECUTABLE", raising=False)
    return tmp_path


def checks() -> dict:
    return {check.name: check for check in network_checks()}


def failing() -> dict:
    return {name: check for name, check in checks().items() if not check.ok}


def test_the_provisioned_stack_has_nothing_that_would_reach_the_network(clean_env):
    found = checks()
    assert failing() == {}
    assert "holds its encoder config and tokenizer" in found["offline: span model"].detail
    assert "embedded kitchen" in found["offline: kitchen"].detail


def test_hub_variables_unset_in_the_users_shell_are_named(clean_env, monkeypatch):
    monkeypatch.setattr(offline, "as_given", {"HF_HUB_OFFLINE": None, "TRANSFORMERS_OFFLINE": "1"})
    detail = checks()["offline: hub variables"].detail
    assert "HF_HUB_OFFLINE" in detail and "TRANSFORMERS_OFFLINE" not in detail.split("for itself")[0]
    monkeypatch.setattr(offline, "as_given", {"HF_HUB_OFFLINE": "1"})
    assert "in your shell too" in checks()["offline: hub variables"].detail


def test_a_url_in_a_path_variable_is_named(clean_env, monkeypatch):
    monkeypatch.setenv("COOK2LTL_LIBRARY", "https://example.org/library.sqlite")
    check = failing()["offline: COOK2LTL_LIBRARY"]
    assert "is a URL" in check.detail and check.fix


def test_a_hub_name_as_span_checkpoint_is_named(clean_env):
    (clean_env / "absent.toml").write_text('[ner]\ncheckpoint = "urchade/gliner_small-v2.1"\n')
    check = failing()["offline: span model"]
    assert "urchade/gliner_small-v2.1" in check.detail and "hub" in check.detail and "absent.toml" in check.fix


def test_a_checkpoint_that_needs_its_encoder_from_the_hub_is_named_unless_cached(clean_env):
    checkpoint = clean_env / "lab-gliner"
    checkpoint.mkdir()
    (checkpoint / "gliner_config.json").write_text(json.dumps({"model_name": "microsoft/deberta-v3-small",
                                                              "encoder_config": None}))
    (clean_env / "absent.toml").write_text(f'[ner]\ncheckpoint = "{checkpoint}"\n')
    assert "would download" in failing()["offline: span model"].detail
    (clean_env / "hf" / "hub" / "models--microsoft--deberta-v3-small" / "snapshots").mkdir(parents=True)
    assert "local hub cache" in checks()["offline: span model"].detail and failing() == {}


def test_a_thor_executable_that_is_not_one_is_named(clean_env, monkeypatch):
    monkeypatch.setenv("COOK2LTL_THOR_EXECUTABLE", str(clean_env / "thor-Linux64"))
    check = failing()["offline: kitchen"]
    assert "is not an executable file" in check.detail and "COOK2LTL_THOR_EXECUTABLE" in check.fix


def test_a_broken_settings_file_is_reported_not_raised(clean_env):
    (clean_env / "absent.toml").write_text("[limits\n")
    assert "not valid TOML" in failing()["offline: settings"].detail
