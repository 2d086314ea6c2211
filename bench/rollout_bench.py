"""Success and seconds per rollout of the kitchen tasks, planned by a language model (the paper's Table II).

    .venv/bin/python bench/rollout_bench.py [--runs 10] [--model qwen2.5-coder-1.5b] [--tasks paper|suite|all]
                                            [--variant AR+A|AR] [--json results.json]

One variant at a time; `cook2ltl bench table2` runs AR and AR+A side by side. The measuring code is
cook2ltl.bench.table2 (its docstring says what is measured).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from cook2ltl import offline
from cook2ltl.bench.table2 import TASK_SETS, choose_tasks, rollout_runs, summary
from cook2ltl.pipeline.records import Variant
from cook2ltl.assembly.backends import DEFAULT_MODEL


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--model", default=DEFAULT_MODEL)
    parser.add_argument("--tasks", choices=TASK_SETS, default="all")
    parser.add_argument("--variant", type=Variant, choices=(Variant.AR, Variant.AR_LIBRARY), default=Variant.AR_LIBRARY)
    parser.add_argument("--json", type=Path, help="also write every run to this file")
    args = parser.parse_args()
    offline.enforce()
    tasks = choose_tasks(args.tasks)
    record = rollout_runs(args.model, args.variant, args.runs, tasks, lambda text: print(text, flush=True))
    paper = [r for t in tasks if t.source.startswith("paper") for r in record["tasks"][t.id]]
    suite = [r for t in tasks if not t.source.startswith("paper") for r in record["tasks"][t.id]]
    for name, rows in (("paper tasks", paper), ("suite", suite)):
        if rows:
            print(summary(name, rows, args.runs))
    if args.json:
        args.json.write_text(json.dumps(record, indent=2, ensure_ascii=False))


if __name__ == "__main__":
    sys.exit(main())
