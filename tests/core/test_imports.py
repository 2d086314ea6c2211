"""The core stays fast to import: heavy backends load only when a model is first used."""

import json
import subprocess
import sys

HEAVY = ["torch", "gliner", "spacy", "transformers", "llama_cpp", "ai2thor", "textual"]


def test_cli_and_core_import_no_model_library():
    code = (
        "import sys, json\n"
        "import cook2ltl.cli, cook2ltl.parse, cook2ltl.stack, cook2ltl.doctor, cook2ltl.models.provision\n"
        f"print(json.dumps([m for m in {HEAVY!r} if m in sys.modules]))"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert json.loads(result.stdout) == []
