"""One Table I from several `cook2ltl bench table1` results (one folder per model, seed or variant), beside the
paper: `cook2ltl bench table1 --combine A/table1.json --combine B/table1.json [--finished]`.

The sources must cover the same recipes; the library bound is the first source's that has one. With `finished`,
runs stopped before the last recipe are left out.
"""

from __future__ import annotations

import json
from pathlib import Path

from cook2ltl import files, paths
from cook2ltl.bench.results import write
from cook2ltl.bench.table1 import table1_markdown
from cook2ltl.errors import UserError

RESULT_BYTES = 20_000_000  # a table1.json of 50 recipes, 7 variants and 10 runs is under 1 MB
HINT = "give the table1.json files that `cook2ltl bench table1` wrote."


def combine_table1(sources: list[Path], finished: bool, out: Path) -> dict:
    """Write <out>/table1.json (every run of every source, or the finished ones) and <out>/table1.md."""
    records = [read_table1(path) for path in sources]
    totals = {record["recipes"] for record in records}
    if len(totals) != 1:
        raise UserError(f"The results cover different numbers of recipes: {sorted(totals)}.",
                        "combine results of the same recipes (the same --recipes).")
    total = totals.pop()
    rows = [row for record in records for row in record["runs"] if not finished or row["recipes_done"] == total]
    bound = next((record["library_bound"] for record in records if record.get("library_bound")), None)
    combined = {"sources": [{"file": str(path), "command": record.get("command"), "machine": record.get("machine")}
                            for path, record in zip(sources, records)],
                "recipes": total, "library_bound": bound, "runs": rows}
    write(out, "table1", combined, table1_markdown(rows, total, bound))
    return combined


def read_table1(value: Path) -> dict:
    path = paths.user_path(value, "--combine")
    text = files.read_text(path, RESULT_BYTES, "Table I result", HINT)
    try:
        record = json.loads(text)
    except (ValueError, RecursionError) as error:
        raise UserError(f"The Table I result {paths.shown(path)} is not JSON: {error}.", HINT) from None
    if not (isinstance(record, dict) and record.get("benchmark") == "table1" and isinstance(record.get("runs"), list)
            and isinstance(record.get("recipes"), int)):
        raise UserError(f"{paths.shown(path)} is not a Table I result (no benchmark \"table1\", runs and recipes).",
                        HINT)
    return record
