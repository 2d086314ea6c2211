"""The paper's ablation (Table I) on its 50 evaluation recipes: LLM calls, tokens and time per variant.

    .venv/bin/python bench/translate_50.py [--model qwen2.5-coder-1.5b] [--variants AR* AR AR+A] [--limit 50]

The recipes are parsed once with the real parser; AR+A starts from an empty library and grows it over
the 50 recipes in order, as in the paper. Which actions reach the model depends only on the parse and the
variant, so the call counts of AR* and AR hold for any model.
"""

from __future__ import annotations

import argparse
import csv
import tempfile
import time
from pathlib import Path

from cook2ltl import offline, paths
from cook2ltl.library import Library
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline import Finished, Translator, Variant, translate
from cook2ltl.reduce.llm import DEFAULT_MODEL, load_model
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.settings import load_settings
from cook2ltl.stack import dependency_parser, span_extractor


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default=DEFAULT_MODEL)
    parser.add_argument("--variants", nargs="+", default=["AR*", "AR", "AR+A"])
    parser.add_argument("--limit", type=int, default=50)
    args = parser.parse_args()
    offline.enforce()
    source = paths.shared_data_dir() / "cook2ltl" / "eval_recipes_50.csv"
    with source.open(encoding="utf-8") as handle:
        texts = [row["Edited text"] for row in csv.DictReader(handle)][: args.limit]
    spans, dependencies = span_extractor(load_settings()), dependency_parser()
    started = time.perf_counter()
    parsed = [parse_recipe(text, spans, dependencies) for text in texts]
    print(f"{len(parsed)} recipes parsed in {time.perf_counter() - started:.0f} s")
    model, primitives = load_model(args.model), load_primitives("recipe")
    print("| variant | actions | primitive | library hits | LLM calls | prompt tokens | completion tokens | LLM s | s |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name in args.variants:
        variant = Variant(name)
        with tempfile.TemporaryDirectory() as folder:
            library = Library(Path(folder) / "library.sqlite") if variant == Variant.AR_LIBRARY else None
            translator = Translator(primitives, model, library, variant)
            totals: dict[str, float] = {}
            for recipe in parsed:
                stats = next(e for e in translate(recipe, translator) if isinstance(e, Finished)).translation.stats
                for key, value in vars(stats).items():
                    totals[key] = totals.get(key, 0) + value
            if library is not None:
                library.close()
        print(f"| {name} | {totals['actions']:.0f} | {totals['primitive']:.0f} | {totals['library_hits']:.0f} "
              f"| {totals['llm_calls']:.0f} | {totals['prompt_tokens']:.0f} | {totals['completion_tokens']:.0f} "
              f"| {totals['llm_seconds']:.0f} | {totals['seconds']:.0f} |", flush=True)


if __name__ == "__main__":
    main()
