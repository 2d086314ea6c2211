"""Fine-tune a GLiNER span model on the paper's brat annotations, seeded and reproducible.

`train` is a generator: it yields `TrainingProgress` as it goes and returns the report, so a CLI bar or a
TUI worker can show progress without the loop knowing about either.
"""

from __future__ import annotations

import hashlib
import json
import random
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Generator, Mapping

from cook2ltl import offline
from cook2ltl.domain.recipe import Label
from cook2ltl.parse.gliner_spans import LABELS_FILE
from cook2ltl.parse.training.brat import read_corpus
from cook2ltl.parse.training.examples import is_validation, sentence_examples, to_gliner

# The checkpoint's names for the six categories: GLiNER reads them as prompts.
DEFAULT_LABEL_NAMES: dict[Label, str] = {
    Label.VERB: "cooking action",
    Label.WHAT: "object",
    Label.WHERE: "location",
    Label.HOW: "manner",
    Label.TIME: "time",
    Label.TEMP: "temperature",
}


@dataclass(frozen=True)
class TrainConfig:
    seed: int = 13
    epochs: int = 16  # Temperature, the rarest category, is learned last: F1 0 at 10 epochs, 0.36 at 12
    batch_size: int = 8
    encoder_lr: float = 1e-4
    head_lr: float = 6e-4  # 1e-3 without warm-up kills the span head within a few steps
    # Focal loss: few spans of many candidates are entities; plain BCE settles on "nothing anywhere".
    focal_alpha: float = 0.75
    focal_gamma: float = 2.0
    warmup: float = 0.1  # share of steps with a rising learning rate, so a fresh head is not knocked dead
    max_width: int = 12
    dropout: float = 0.1
    threads: int = 1  # one torch thread trains faster than two on this class of machine
    label_names: Mapping[Label, str] = field(default_factory=lambda: dict(DEFAULT_LABEL_NAMES))


@dataclass(frozen=True)
class TrainingProgress:
    epoch: int
    step: int
    total_steps: int
    loss: float
    elapsed: float


def fingerprint(data_dir: Path, config: TrainConfig) -> str:
    """Changes whenever the data or the recipe changes, so the cache knows when to retrain."""
    digest = hashlib.sha256(json.dumps(_config_json(config), sort_keys=True).encode())
    for path in sorted(data_dir.glob("recipe*")):
        digest.update(path.name.encode() + path.read_bytes())
    return digest.hexdigest()


def train(data_dir: Path, encoder_dir: Path, output_dir: Path, config: TrainConfig = TrainConfig()
          ) -> Generator[TrainingProgress, None, dict]:
    torch, model_class, config_class = _import_backend(config)
    random.seed(config.seed)
    torch.manual_seed(config.seed)

    recipes = read_corpus(data_dir)
    train_set = sentence_examples(r for r in recipes if not is_validation(r.name))
    batches = [g for g in (to_gliner(e, config.label_names) for e in train_set) if g]

    gliner_config = config_class(
        model_name=str(encoder_dir), span_mode="markerV0", max_width=config.max_width,
        hidden_size=384, dropout=config.dropout, max_len=384, max_types=len(Label),
    )
    model = model_class.load_from_config(gliner_config, backbone_from_pretrained=True, local_files_only=True)
    model.train()
    collate = model._create_data_collator()
    encoder = [p for n, p in model.named_parameters() if "token_rep_layer" in n]
    encoder_ids = {id(p) for p in encoder}
    head = [p for p in model.parameters() if id(p) not in encoder_ids]
    optimizer = torch.optim.AdamW([{"params": encoder, "lr": config.encoder_lr}, {"params": head, "lr": config.head_lr}])
    steps_per_epoch = (len(batches) + config.batch_size - 1) // config.batch_size
    total = steps_per_epoch * config.epochs
    scheduler = torch.optim.lr_scheduler.LambdaLR(optimizer, warmup_then_decay(total, config.warmup))

    order = random.Random(config.seed)
    started, step = time.perf_counter(), 0
    for epoch in range(1, config.epochs + 1):
        order.shuffle(batches)
        for first in range(0, len(batches), config.batch_size):
            batch = collate(batches[first:first + config.batch_size])
            loss = model(**batch, alpha=config.focal_alpha, gamma=config.focal_gamma).loss
            loss.backward()
            torch.nn.utils.clip_grad_norm_(model.parameters(), 10.0)
            optimizer.step()
            scheduler.step()
            optimizer.zero_grad()
            step += 1
            yield TrainingProgress(epoch, step, total, loss.item(), time.perf_counter() - started)

    model.eval()
    output_dir.mkdir(parents=True, exist_ok=True)
    model.save_pretrained(str(output_dir))
    report = {
        "labels": {label.value: name for label, name in config.label_names.items()},
        "config": _config_json(config),
        "training_sentences": len(batches),
        "training_seconds": round(time.perf_counter() - started, 1),
        "validation_recipes": sorted({r.name for r in recipes if is_validation(r.name)}),
        "skipped_annotations": [f"{r.name}: {s}" for r in recipes for s in r.skipped],
    }
    (output_dir / LABELS_FILE).write_text(json.dumps(report, indent=2))
    return report


def warmup_then_decay(total: int, warmup: float):
    """Learning-rate factor per step: linear up over the warm-up, then linear down to zero."""
    rising = max(1, int(total * warmup))
    return lambda step: (step + 1) / rising if step < rising else max(0.0, (total - step) / max(1, total - rising))


def _config_json(config: TrainConfig) -> dict:
    values = asdict(config)
    values["label_names"] = {str(k): v for k, v in config.label_names.items()}
    values.pop("threads")  # speed only: the same weights come out
    return values


def _import_backend(config: TrainConfig):
    offline.enforce()
    # heavy: torch and GLiNER (seconds) load only to train, after offline.enforce()
    import torch
    from gliner import GLiNERConfig
    from gliner.model import UniEncoderSpanGLiNER

    torch.set_num_threads(config.threads)
    return torch, UniEncoderSpanGLiNER, GLiNERConfig
