"""`cook2ltl bench fuzz`: every boundary's fuzzing target run long, with the count of inputs tried.

The targets are the hypothesis tests of tests/reliability/test_fuzz_*.py: `make test` runs them briefly (60
examples each); here each gets `examples`. A target fails on any exception other than the clear errors it
allows, on an example that runs past its deadline (a hang), or on a library left changed; the record lists
the inputs each boundary was tried with and the targets that failed.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from cook2ltl import paths
from cook2ltl.bench.results import write
from cook2ltl.errors import UserError

TARGETS = "test_fuzz_*.py"
_OUTCOME = re.compile(r"(\d+) (passed|failed|error|errors)\b")


def run_fuzz(examples: int, out: Path, echo: Callable[[str], None]) -> dict:
    folder = paths.PROJECT_ROOT / "tests" / "reliability"
    targets = sorted(folder.glob(TARGETS))
    if not targets:
        raise UserError(f"no fuzzing targets ({TARGETS}) in {folder}", "run from a checkout of cook2ltl.")
    echo(f"fuzzing {len(targets)} target files, {examples} examples per target …")
    with tempfile.TemporaryDirectory() as scratch:
        counts_file = Path(scratch) / "tried.json"
        env = {**os.environ, "COOK2LTL_FUZZ_EXAMPLES": str(examples), "COOK2LTL_FUZZ_COUNTS": str(counts_file)}
        started = time.perf_counter()
        run = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", *map(str, targets)],
                             cwd=paths.PROJECT_ROOT, env=env, capture_output=True, text=True)
        seconds = time.perf_counter() - started
        tried = json.loads(counts_file.read_text(encoding="utf-8")) if counts_file.is_file() else {}
    outcome = {kind.rstrip("s"): int(n) for n, kind in _OUTCOME.findall(run.stdout.strip().splitlines()[-1])} \
        if run.stdout.strip() else {}
    failed = [line.split(" ", 1)[1] for line in run.stdout.splitlines() if line.startswith(("FAILED ", "ERROR "))]
    record = {"examples_per_target": examples, "tried": tried, "inputs": sum(tried.values()),
              "passed": outcome.get("passed", 0), "failed": failed, "seconds": round(seconds, 1)}
    write(out, "fuzz", record, fuzz_markdown(record))
    echo(f"{record['inputs']} inputs, {len(failed)} failing targets, {seconds / 60:.1f} min")
    return record


def fuzz_markdown(record: dict) -> str:
    rows = "\n".join(f"| {boundary} | {count} |" for boundary, count in sorted(record["tried"].items()))
    verdict = ("every target passed: 0 tracebacks, hangs or losses" if not record["failed"]
               else "failing targets: " + "; ".join(record["failed"]))
    return (f"| boundary | inputs tried |\n|---|---|\n{rows}\n\n{record['inputs']} inputs in {record['seconds']} s, "
            f"{record['examples_per_target']} examples per target; {verdict}.\n")
