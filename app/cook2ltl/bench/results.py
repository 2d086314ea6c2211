"""What every benchmark writes: a JSON record with the command and the machine, and a markdown table."""

from __future__ import annotations

import json
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

from cook2ltl import paths


def mean_std(values: list[float]) -> tuple[float, float]:
    """Mean and sample standard deviation (0 for a single run), as the paper reports them."""
    if not values:
        return 0.0, 0.0
    return statistics.mean(values), statistics.stdev(values) if len(values) > 1 else 0.0


def pm(values: list[float], digits: int = 2) -> str:
    mean, std = mean_std(values)
    return f"{mean:.{digits}f} ± {std:.{digits}f}"


def machine() -> dict:
    """Where and from what a result was measured."""
    return {
        "cpus": os.cpu_count(),
        "load_average": [round(v, 2) for v in os.getloadavg()],
        "nice": os.nice(0),  # a benchmark run at low priority on a shared machine measures the sharing too
        "python": platform.python_version(),
        "platform": platform.platform(),
        "commit": _commit(),
        "at": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
    }


def command_line() -> str:
    return " ".join(["cook2ltl", *sys.argv[1:]]) if Path(sys.argv[0]).name == "cook2ltl" else " ".join(sys.argv)


def write(out: Path, name: str, record: dict, markdown: str) -> tuple[Path, Path]:
    """`out/name.json` and `out/name.md`, each written whole (a reader never sees half a file)."""
    out.mkdir(parents=True, exist_ok=True)
    record = {"benchmark": name, "command": command_line(), "machine": machine(), **record}
    json_path, md_path = out / f"{name}.json", out / f"{name}.md"
    _replace(json_path, json.dumps(record, indent=2, ensure_ascii=False) + "\n")
    where = record["machine"]
    load = " / ".join(f"{v:.1f}" for v in where["load_average"])
    _replace(md_path, f"<!-- {record['command']} -->\n{markdown.rstrip()}\n\n_Measured on {where['cpus']} CPUs at nice "
                      f"{where['nice']}, load average {load} (1 / 5 / 15 min) when written, commit {where['commit']}, "
                      f"{where['at']}._\n")
    return json_path, md_path


def _replace(path: Path, text: str) -> None:
    partial = path.with_suffix(path.suffix + ".partial")
    partial.write_text(text, encoding="utf-8")
    partial.replace(path)


def _commit() -> str | None:
    try:
        found = subprocess.run(["git", "-C", str(paths.PROJECT_ROOT), "rev-parse", "--short", "HEAD"],
                               capture_output=True, text=True, timeout=5)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return found.stdout.strip() or None
