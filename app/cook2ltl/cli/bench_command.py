"""`cook2ltl bench`: the paper's Tables I and II, the span model against a spaCy baseline, micro timings, action
reduction per model, and the fuzzing targets run long."""

from __future__ import annotations

from enum import StrEnum
from pathlib import Path
from typing import Optional

import typer

from cook2ltl import paths
from cook2ltl.assembly.backends import DEFAULT_MODEL
from cook2ltl.errors import UserError
from cook2ltl.text_safety import terminal

SMOKE_MODEL = "smollm2-135m"


class Benchmark(StrEnum):
    TABLE1 = "table1"
    TABLE2 = "table2"
    NER = "ner"
    MICRO = "micro"
    REDUCE = "reduce"
    FUZZ = "fuzz"
    ALL = "all"


def bench_command(
    which: Benchmark = typer.Argument(Benchmark.ALL, help="Which benchmark; `all` runs them in this order."),
    runs: Optional[int] = typer.Option(None, help="Seeded runs of Table I (default 3) or consecutive runs per "
                                                    "task of Table II (default 10)."),
    model: Optional[str] = typer.Option(None, help="Language model of the manifest (default: the translator's; "
                                                   "reduce compares smollm2-135m and qwen2.5-coder-1.5b)."),
    smoke: bool = typer.Option(False, help="A tiny, fast pass over everything (1 recipe, smollm2, 1 run): "
                                           "checks the benchmarks work, measures nothing worth keeping."),
    out: Path = typer.Option(Path("bench/results"), help="Folder for the JSON and markdown results."),
    variant: Optional[list[str]] = typer.Option(
        None, help="Variants, repeatable. Table I: AR+A, 'AR+A warm', 'AR+A approved-only', AR, AR*, 'AR+A world', "
                   "'AR+A repair' (default all, in this order); Table II: AR, AR+A, 'AR+A repair', 'AR+A world'."),
    recipes: Optional[int] = typer.Option(None, help="Table I on the first N of the 50 recipes only."),
    tasks: str = typer.Option("paper", help="Table II tasks: paper (the 4 of the paper), suite, all (the 33 of "
                                            "tasks.toml) or paraphrase (the held-out paraphrases.toml)."),
    primitives: str = typer.Option("recipe", help="Table I: the primitive set, recipe or ai2thor (its world model "
                                                  "is THOR's, and the kitchen still checks every plan)."),
    seed: Optional[int] = typer.Option(None, help="Table I: the first run's seed; later runs take the next ones. "
                                                  "Run 4242 (the default) meets the recipes in the file's order, "
                                                  "others in an order shuffled by their seed."),
    examples: int = typer.Option(2000, min=1, max=1_000_000, help="Fuzz: examples per fuzzing target "
                                                                   "(make test runs 60)."),
    combine: Optional[list[Path]] = typer.Option(
        None, help="Table I: combine these table1.json results (repeatable) into <out>/table1.json and .md instead "
                   "of running."),
    finished: bool = typer.Option(False, help="With --combine: leave out runs stopped before the last recipe."),
    workers: int = typer.Option(1, min=1, max=8, help="Table I's world variant: recipes translated side by side, "
                                                      "their model calls decoded in one batch."),
) -> None:
    """Measure and write bench/results/<name>.json and .md (a benchmark, not a test: it takes long)."""
    if (combine or finished) and (which != Benchmark.TABLE1 or not combine):
        raise UserError("--combine (and --finished) make Table I from results already written.",
                        "cook2ltl bench table1 --combine A/table1.json --combine B/table1.json [--finished]")
    console = terminal(stderr=True)
    echo = lambda text: console.print(text, highlight=False, soft_wrap=True)  # noqa: E731
    out = paths.output_folder(out, "--out")  # made now: a bad folder fails before the benchmark, not after it
    if combine:
        from cook2ltl.bench.combine import combine_table1  # loaded only when it runs

        combine_table1(combine, finished, out)
        echo((out / "table1.md").read_text(encoding="utf-8"))
        return
    named_model = model
    model = model or (SMOKE_MODEL if smoke else DEFAULT_MODEL)
    chosen = [b for b in Benchmark if b != Benchmark.ALL] if which == Benchmark.ALL else [which]
    if Benchmark.TABLE1 in chosen:
        from cook2ltl.bench.table1 import (  # loaded only when chosen
            FIRST_SEED,
            SMOKE_VARIANTS,
            VARIANTS,
            run_table1,
        )

        chosen_variants = tuple(variant or (SMOKE_VARIANTS if smoke else VARIANTS))
        run_table1(model, 1 if smoke else runs or 3, chosen_variants, 1 if smoke else recipes, out, echo,
                   FIRST_SEED if seed is None else seed, primitives, workers)
    if Benchmark.TABLE2 in chosen:
        from cook2ltl.bench.table2 import COLUMNS, run_table2  # loaded only when chosen

        run_table2(model, 1 if smoke else runs or 10, "smoke" if smoke else tasks, out, echo, tuple(variant or COLUMNS))
    if Benchmark.NER in chosen:
        from cook2ltl.bench.ner import run_ner  # loaded only when chosen

        run_ner(smoke, out, echo)
    if Benchmark.MICRO in chosen:
        from cook2ltl.bench.micro import run_micro  # loaded only when chosen

        run_micro(model, smoke, out, echo)
    if Benchmark.REDUCE in chosen:
        from cook2ltl.bench.reduce import MODELS, run_reduce  # loaded only when chosen

        run_reduce((model,) if named_model or smoke else MODELS, smoke, out, echo)
    if Benchmark.FUZZ in chosen:
        from cook2ltl.bench.fuzz import run_fuzz  # loaded only when chosen

        run_fuzz(20 if smoke else examples, out, echo)
    echo(f"results in {out}/")
