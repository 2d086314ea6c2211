"""Recipe text at the edges: empty, huge, many steps, hidden characters, binary, not UTF-8, limits from settings."""

import pytest

from cook2ltl.domain.settings import Limits
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.errors import UserError
from cook2ltl.parse import parse_recipe
from cook2ltl.preprocess import visible_text
from cook2ltl.preprocess.recipe_file import read_recipe
from tests.fakes import ScriptedDependencies, ScriptedSpans

SMALL = Limits(recipe_bytes=1000, steps=5)


def parse(text, limits=Limits(), script=None):
    return parse_recipe(text, ScriptedSpans(script or {}), ScriptedDependencies(), limits)


@pytest.mark.parametrize("text", ["", "   \n\t\n  ", "...\n---\n!!!", "\u200b\u200d\ufeff", "🍳🍳 🥚"])
def test_a_recipe_without_words_is_a_clear_error(text):
    with pytest.raises(UserError, match="The recipe is empty"):
        parse(text)


def test_a_recipe_over_the_size_limit_is_refused_before_any_model_runs():
    class Untouchable:
        def extract(self, sentences):
            raise AssertionError("the span model ran on an oversized recipe")

    with pytest.raises(UserError, match="1,001 bytes; the limit is 1,000") as raised:
        parse_recipe("a" * 1001, Untouchable(), ScriptedDependencies(), SMALL)
    assert "recipe_bytes" in raised.value.hint
    one_megabyte = "Boil the eggs. " * 70_000
    with pytest.raises(UserError, match="the limit is 200,000"):
        parse_recipe(one_megabyte, Untouchable(), ScriptedDependencies(), Limits())


def test_ten_thousand_steps_are_refused_with_the_count():
    with pytest.raises(UserError, match="10,000 steps; the limit is 500"):
        parse("\n".join(["Stir."] * 10_000))
    assert len(parse("\n".join(["Stir."] * 5), SMALL).steps) == 5
    with pytest.raises(UserError, match="6 steps; the limit is 5"):
        parse("\n".join(["Stir."] * 6), SMALL)


def test_hidden_characters_become_spaces_and_offsets_still_point_into_the_input():
    text = "\u202eBoil the\u200b eggs.\u202c Add\x00 salt\ufeff."
    cleaned = visible_text(text)
    assert len(cleaned) == len(text) and "\u202e" not in cleaned and "\x00" not in cleaned
    recipe = parse(text)
    assert [step.sentence.text for step in recipe.steps] == ["Boil the  eggs.", "Add  salt ."]
    for step in recipe.steps:
        assert text[step.sentence.start:step.sentence.end].replace("\u200b", " ").replace("\x00", " ") \
            .replace("\ufeff", " ") == step.sentence.text
    assert visible_text("Crème brûlée, 2 °C, 🍳, שלום") == "Crème brûlée, 2 °C, 🍳, שלום"  # visible text is kept


def test_a_span_of_marks_alone_is_no_argument():
    sentence = "Stir the sauce\u0301\u0301 gently."
    recipe = parse(sentence, script={sentence: [("VERB", "Stir"), ("WHAT", "the sauce"), ("HOW", "\u0301\u0301")]})
    frame = recipe.steps[0].frames[0]
    assert frame.name == "stir" and [a.span.text for a in frame.what] == ["the sauce"] and not frame.how


def test_recipe_files_that_are_not_text(tmp_path):
    cases = {
        "binary.bin": (bytes(range(256)) * 4, "looks binary"),
        "latin1.txt": ("Crème brûlée".encode("latin-1"), r"is not UTF-8 text \(byte 2\)"),
        "utf16.txt": ("Boil the eggs.".encode("utf-16"), "looks binary"),
        "huge.txt": (b"Stir. " * 40_000, "larger than the limit of 200,000 bytes"),
    }
    for name, (data, message) in cases.items():
        (tmp_path / name).write_bytes(data)
        with pytest.raises(UserError, match=message):
            read_recipe(str(tmp_path / name), 200_000)
    with pytest.raises(UserError, match="No recipe file"):
        read_recipe(str(tmp_path / "absent.txt"))
    with pytest.raises(UserError, match="Cannot read the recipe file .*: it is a folder"):
        read_recipe(str(tmp_path))
    (tmp_path / "bom.txt").write_bytes("\ufeffBoil the eggs.".encode("utf-8"))
    assert read_recipe(str(tmp_path / "bom.txt"), 100) == "Boil the eggs."


def test_limits_come_from_the_settings_file(tmp_path):
    config = tmp_path / "config.toml"
    config.write_text("[limits]\nrecipe_bytes = 5000\nsteps = 20\nllm_seconds = 30\n")
    assert load_settings(config).limits == Limits(recipe_bytes=5000, steps=20, llm_seconds=30.0)
    assert load_settings(tmp_path / "absent.toml").limits == Limits()
    for bad in ("steps = 0", 'steps = "many"', "recipe_bytes = -1", "steps = true", "pages = 3"):
        config.write_text(f"[limits]\n{bad}\n")
        with pytest.raises(UserError, match=r"\[limits\]"):
            load_settings(config)


def test_a_settings_path_that_is_a_folder_is_a_clear_error(tmp_path):
    with pytest.raises(UserError, match="Cannot read the settings file"):
        load_settings(tmp_path)


def test_a_models_folder_that_is_a_file_is_a_clear_error(tmp_path):
    from cook2ltl.assembly.manifest import load_manifest

    (tmp_path / "models").write_text("not a folder")
    with pytest.raises(UserError):
        load_manifest(tmp_path / "models")
