"""Keep model libraries from reaching for a hub, and quiet: set before any of them is imported."""

import os

OFFLINE_VARIABLES = {"HF_HUB_OFFLINE": "1", "TRANSFORMERS_OFFLINE": "1", "HF_DATASETS_OFFLINE": "1"}
# Their own progress bars and advice would garble our rich output.
QUIET_VARIABLES = {"TRANSFORMERS_VERBOSITY": "error", "HF_HUB_DISABLE_PROGRESS_BARS": "1", "TQDM_DISABLE": "1"}


def enforce() -> None:
    for name, value in OFFLINE_VARIABLES.items():
        os.environ[name] = value
    for name, value in QUIET_VARIABLES.items():
        os.environ.setdefault(name, value)
    # llama.cpp's OpenMP threads spin while waiting unless told otherwise.
    os.environ.setdefault("OMP_WAIT_POLICY", "passive")
