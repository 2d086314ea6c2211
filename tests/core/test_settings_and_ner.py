from pathlib import Path

import pytest

from cook2ltl.assembly.backends import span_extractor
from cook2ltl.domain.recipe import Label, Span
from cook2ltl.domain.settings import Settings
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.errors import UserError
from cook2ltl.parse.training.brat import read_recipe
from cook2ltl.parse.training.evaluate import strict_f1
from cook2ltl.parse.training.examples import SentenceExample, is_validation, to_gliner


def test_settings_read_a_lab_checkpoint_and_its_label_names(tmp_path):
    config = tmp_path / "config.toml"
    config.write_text('[ner]\ncheckpoint = "/labs/gliner"\nthreshold = 0.4\n[ner.labels]\nverb = "action"\n')
    settings = load_settings(config)
    assert str(settings.ner.checkpoint) == "/labs/gliner"
    assert settings.ner.labels == {Label.VERB: "action"} and settings.ner.threshold == 0.4


def test_settings_read_a_keymap(tmp_path):
    config = tmp_path / "config.toml"
    config.write_text('[keymap]\n"translate.run" = "f5"\n"library.approve" = "y,a"\n')
    assert load_settings(config).keymap == {"translate.run": "f5", "library.approve": "y,a"}


def test_settings_read_the_labs_primitive_sets_and_repairs(tmp_path, monkeypatch):
    monkeypatch.setenv("HOME", str(tmp_path))
    config = tmp_path / "config.toml"
    config.write_text('[translate]\nprimitives = ["~/robot.toml", "/labs/arm.toml"]\nrepairs = 0\n')
    translate = load_settings(config).translate
    assert translate.primitives == (tmp_path / "robot.toml", Path("/labs/arm.toml")) and translate.repairs == 0
    assert Settings().translate.primitives == () and Settings().translate.repairs == 2


@pytest.mark.parametrize("content", ["[ner\n", '[ner.labels]\nCOLOUR = "x"\n', '[ner]\nthreshold = "high"\n',
                                     'keymap = 3\n', '[keymap]\n"translate.run" = 5\n', '[keymap]\nx = " "\n',
                                     '[translate]\nrepairs = 11\n', '[translate]\nrepairs = true\n',
                                     '[translate]\nprimitives = "robot.toml"\n', '[translate]\nrepair = 1\n'])
def test_bad_settings_are_user_errors(tmp_path, content):
    config = tmp_path / "config.toml"
    config.write_text(content)
    with pytest.raises(UserError):
        load_settings(config)


def test_a_lab_checkpoint_needs_names_for_every_category(tmp_path):
    checkpoint = tmp_path / "gliner-lab"
    checkpoint.mkdir()
    from cook2ltl.domain.settings import NerSettings

    with pytest.raises(UserError, match="No label names"):
        span_extractor(Settings(ner=NerSettings(checkpoint=checkpoint, labels={Label.VERB: "action"})))
    names = {label: label.value.lower() for label in Label}
    assert span_extractor(Settings(ner=NerSettings(checkpoint=checkpoint, labels=names))).label_names == names


def test_brat_reader_reanchors_drifted_offsets_and_skips_lost_ones(tmp_path):
    (tmp_path / "recipe7.txt").write_text("Preheat the oven. Stir the soup.")
    (tmp_path / "recipe7.ann").write_text(
        "T1\tVERB 0 7\tPreheat\nT2\tWHAT 14 18\toven\nT3\tWHAT 0 5\tbroth\nT4\tCOLOUR 0 3\tPre\n")
    recipe = read_recipe(tmp_path / "recipe7.txt")
    assert [(s.label, s.start, s.text) for s in recipe.spans] == [(Label.VERB, 0, "Preheat"), (Label.WHAT, 12, "oven")]
    assert recipe.repaired == 1 and len(recipe.skipped) == 2


def test_gliner_examples_use_word_indices_and_drop_unaligned_spans():
    example = SentenceExample("r", "Cook the penne.", (Span(Label.VERB, 0, 4, "Cook"), Span(Label.WHAT, 9, 14, "penne"),
                                                       Span(Label.WHAT, 10, 14, "enne")))
    converted = to_gliner(example, {Label.VERB: "verb", Label.WHAT: "what"})
    assert converted == {"tokenized_text": ["Cook", "the", "penne", "."], "ner": [[0, 0, "verb"], [2, 2, "what"]]}


def test_validation_split_is_every_fifth_recipe():
    held_out = [n for n in range(70) if is_validation(f"recipe{n}")]
    assert len(held_out) == 14 and held_out[:3] == [4, 9, 14]


def test_strict_f1_counts_only_exact_label_and_boundaries():
    gold = [[Span(Label.VERB, 0, 4, "Cook"), Span(Label.WHAT, 9, 14, "penne")]]
    predicted = [[Span(Label.VERB, 0, 4, "Cook"), Span(Label.WHAT, 5, 14, "the penne"), Span(Label.HOW, 0, 4, "Cook")]]
    report = strict_f1(gold, predicted)
    assert report.overall.true_positives == 1 and report.overall.predicted == 3 and report.overall.gold == 2
    assert report.per_label[Label.VERB].f1 == 1.0 and report.per_label[Label.WHAT].f1 == 0.0
    assert round(report.overall.f1, 3) == 0.4
