"""GLiNER as the SpanExtractor: a trained checkpoint folder, or any GLiNER a lab drops in."""

from __future__ import annotations

import json
import threading
from pathlib import Path
from typing import Mapping, Sequence

from cook2ltl import offline
from cook2ltl.domain.recipe import Label, Span
from cook2ltl.errors import UserError

LABELS_FILE = "cook2ltl.json"


def checkpoint_label_names(checkpoint: Path) -> dict[Label, str] | None:
    """The names a checkpoint trained here uses for the six categories, if it says."""
    path = checkpoint / LABELS_FILE
    if not path.exists():
        return None
    return {Label(key): value for key, value in json.loads(path.read_text())["labels"].items()}


class GlinerSpans:
    """Loads the model on first use; the model is shared by threads, loading is not."""

    def __init__(self, checkpoint: Path, label_names: Mapping[Label, str], threshold: float = 0.5,
                 threads: int | None = None) -> None:
        self.checkpoint = checkpoint
        self.label_names = dict(label_names)
        self.threshold = threshold
        self.threads = threads
        self._model = None
        self._lock = threading.Lock()
        self._label_of = {name: label for label, name in self.label_names.items()}

    def extract(self, sentences: Sequence[str]) -> list[list[Span]]:
        model = self._load()
        predictions = model.inference(list(sentences), list(self.label_names.values()), flat_ner=True,
                                      threshold=self.threshold, batch_size=8)
        return [
            [Span(self._label_of[p["label"]], p["start"], p["end"], p["text"], round(float(p["score"]), 3))
             for p in sentence]
            for sentence in predictions
        ]

    def _load(self):
        with self._lock:
            if self._model is None:
                self._model = load_gliner(self.checkpoint, self.threads)
            return self._model


def load_gliner(checkpoint: Path, threads: int | None = None):
    offline.enforce()
    if not (checkpoint / "config.json").exists() and not (checkpoint / "gliner_config.json").exists():
        raise UserError(f"{checkpoint} is not a GLiNER checkpoint folder (no config.json).",
                        "point ner.checkpoint at a folder saved by GLiNER, or run `make models`.")
    # heavy: torch and GLiNER (seconds) load with the span model, after offline.enforce()
    import torch
    from gliner import GLiNER

    if threads:
        torch.set_num_threads(threads)
    model = GLiNER.from_pretrained(str(checkpoint), local_files_only=True, load_tokenizer=True)
    model.eval()
    return model
