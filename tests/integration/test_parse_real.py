"""The trained GLiNER and spaCy's parser on real recipes, through the library and the CLI."""

import csv
import json
import subprocess
import sys
from pathlib import Path

from cook2ltl.domain.recipe import Label
from cook2ltl.parse import parse_recipe

DATA = Path(__file__).parents[1] / "data" / "eval_recipes_50.csv"


def eval_recipes() -> list[str]:
    with DATA.open(encoding="utf-8") as handle:
        return [row["Edited text"] for row in csv.DictReader(handle)]


def test_real_models_find_actions_and_objects(real_parsers):
    recipe = parse_recipe("Preheat the oven to 350 F. Cook the penne in boiling water for 8 minutes.", *real_parsers)
    verbs = [frame.name for step in recipe.steps for frame in step.frames]
    assert "preheat" in verbs and "cook" in verbs
    cook = next(frame for step in recipe.steps for frame in step.frames if frame.name == "cook")
    assert any("penne" in argument.span.text for argument in cook.what)


def test_every_eval_recipe_parses_with_valid_offsets(real_parsers):
    texts = eval_recipes()
    assert len(texts) == 50
    frames = 0
    for text in texts:
        recipe = parse_recipe(text, *real_parsers)
        for step in recipe.steps:
            assert text[step.sentence.start:step.sentence.end] == step.sentence.text
            for span in step.spans:
                assert text[span.start:span.end] == span.text
            frames += len(step.frames)
    assert frames > 100  # the paper counts 275 actions over these recipes


def test_cli_parse_json_carries_labels_and_offsets(tmp_path):
    text = eval_recipes()[0]
    recipe_file = tmp_path / "recipe.txt"
    recipe_file.write_text(text, encoding="utf-8")
    result = subprocess.run([sys.executable, "-m", "cook2ltl", "parse", "--json", str(recipe_file)],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    parsed = json.loads(result.stdout)
    spans = [span for step in parsed["steps"] for span in step["spans"]]
    assert spans and {span["label"] for span in spans} <= {label.value for label in Label}
    for span in spans:
        assert text[span["start"]:span["end"]] == span["text"]


def test_cli_reads_standard_input():
    result = subprocess.run([sys.executable, "-m", "cook2ltl", "parse", "-"], input="Stir the soup.",
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert "stir" in result.stdout.lower()


def test_cli_rejects_binary_input_with_a_message(tmp_path):
    binary = tmp_path / "recipe.bin"
    binary.write_bytes(b"\x00\x01\x02 not text")
    result = subprocess.run([sys.executable, "-m", "cook2ltl", "parse", str(binary)],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 2
    assert "binary" in result.stderr and "Traceback" not in result.stderr
