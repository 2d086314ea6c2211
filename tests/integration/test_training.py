"""Training is seeded: the same data and recipe give the same losses, step by step."""

import shutil
from dataclasses import replace
from pathlib import Path

from cook2ltl.assembly.manifest import load_manifest, model_path
from cook2ltl.parse.training.train import TrainConfig, train
from cook2ltl.paths import models_dir
from tests.models_required import require_models


def losses(data: Path, output: Path) -> list[float]:
    encoder = model_path(load_manifest()["minilm"]) / "model"
    run = train(data, encoder, output, replace(TrainConfig(), epochs=1, batch_size=4))
    return [round(progress.loss, 6) for progress in run]


def test_two_trainings_on_the_same_data_give_the_same_losses(tmp_path):
    require_models("minilm")
    data = tmp_path / "data"
    data.mkdir()
    for name in ("recipe0", "recipe1"):
        for suffix in (".txt", ".ann"):
            shutil.copy(models_dir() / "training" / "brat-dev" / f"{name}{suffix}", data)
    first, second = losses(data, tmp_path / "a"), losses(data, tmp_path / "b")
    assert len(first) >= 3 and first == second
    assert (tmp_path / "a" / "cook2ltl.json").exists()
