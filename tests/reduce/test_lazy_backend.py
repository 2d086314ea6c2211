"""Importing the reduction stage, the pipeline or the command loads no model library."""

import subprocess
import sys


def test_no_llama_cpp_at_import():
    code = ("import sys, cook2ltl.reduce.reduction, cook2ltl.reduce.llm, cook2ltl.pipeline.translator, cook2ltl.cli; "
            "print(sorted({'llama_cpp', 'torch', 'gliner', 'spacy'} & set(sys.modules)))")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert result.stdout.strip() == "[]"
