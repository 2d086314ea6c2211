"""One Table I from several `cook2ltl bench table1` results (one folder per model), beside the paper.

    .venv/bin/python bench/combine_table1.py bench/results/table1-*/table1.json [--out bench/results] [--finished]

Writes <out>/table1.json (every run of every source) and <out>/table1.md. The sources must cover the same
recipes; the library bound is taken from the first source that has it. With --finished, runs stopped before
the last recipe are left out.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from cook2ltl.bench.results import write
from cook2ltl.bench.table1 import table1_markdown


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sources", nargs="+", type=Path)
    parser.add_argument("--out", type=Path, default=Path(__file__).resolve().parent / "results")
    parser.add_argument("--finished", action="store_true", help="leave out runs stopped before the last recipe")
    args = parser.parse_args()
    records = [json.loads(path.read_text()) for path in args.sources]
    totals = {record["recipes"] for record in records}
    if len(totals) != 1:
        raise SystemExit(f"the sources cover different numbers of recipes: {sorted(totals)}")
    rows = [row for record in records for row in record["runs"]
            if not args.finished or row["recipes_done"] == record["recipes"]]
    bound = next((record["library_bound"] for record in records if "library_bound" in record), None)
    combined = {"sources": [{"file": str(path), "command": record["command"], "machine": record["machine"]}
                            for path, record in zip(args.sources, records)],
                "recipes": totals.pop(), "library_bound": bound, "runs": rows}
    write(args.out, "table1", combined, table1_markdown(rows, combined["recipes"], bound))
    print((args.out / "table1.md").read_text())


if __name__ == "__main__":
    main()
