"""Keep model libraries from reaching for a hub: set before any of them is imported."""

import os

OFFLINE_VARIABLES = {"HF_HUB_OFFLINE": "1", "TRANSFORMERS_OFFLINE": "1", "HF_DATASETS_OFFLINE": "1"}


def enforce() -> None:
    for name, value in OFFLINE_VARIABLES.items():
        os.environ[name] = value
    # llama.cpp's OpenMP threads spin while waiting unless told otherwise.
    os.environ.setdefault("OMP_WAIT_POLICY", "passive")
