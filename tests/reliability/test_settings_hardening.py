"""The settings file at its edge: every value typed and bounded, every mistake a one-line UserError that names
the file, the key and what it must be; the Settings API the rest of the code uses unchanged."""

import dataclasses
from pathlib import Path

import pytest

from cook2ltl.domain.recipe import Label
from cook2ltl.domain.settings import Limits, NerSettings, Settings, TranslateSettings
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.errors import UserError


def refused(tmp_path: Path, content: str) -> str:
    config = tmp_path / "settings.toml"
    config.write_text(content, encoding="utf-8")
    with pytest.raises(UserError) as raised:
        load_settings(config)
    message = raised.value.message
    assert "\n" not in message and str(config) in message, message
    return message


@pytest.mark.parametrize("content, expected", [
    # values of the wrong type: each was an AttributeError, TypeError, OverflowError or MemoryError
    ("ner = 5", "ner must be a table, not 5"),
    ("limits = [1, 2]", "limits must be a table, not [1, 2]"),
    ("translate = 'x'", "translate must be a table, not 'x'"),
    ("[limits]\nrecipe_bytes = 1e300", "[limits] recipe_bytes must be a whole number from 1 to 10,000,000, not 1e+300"),
    ("[limits]\nrecipe_bytes = nan", "[limits] recipe_bytes must be a whole number from 1 to 10,000,000, not nan"),
    ("[limits]\nrecipe_bytes = 1000000000000", "not 1000000000000"),
    ("[limits]\nrecipe_bytes = 99999999999999999999999999", "[limits] recipe_bytes must be a whole number"),
    ("[limits]\nsteps = 0.5", "[limits] steps must be a whole number from 1 to 100,000, not 0.5"),
    ("[limits]\nsteps = 0", "[limits] steps must be a whole number from 1 to 100,000, not 0"),
    ("[limits]\nsteps = true", "[limits] steps must be a whole number from 1 to 100,000, not true"),
    ("[limits]\nsteps = 1979-05-27", "[limits] steps must be a whole number"),
    ("[limits]\nllm_seconds = inf", "[limits] llm_seconds must be a number from 1 to 3600, not inf"),
    ("[limits]\nllm_seconds = -1", "[limits] llm_seconds must be a number from 1 to 3600, not -1"),
    ("[ner]\nthreshold = nan", "[ner] threshold must be a number from 0 to 1, not nan"),
    ("[ner]\nthreshold = '0.5'", "[ner] threshold must be a number from 0 to 1, not '0.5'"),
    ("[ner]\ncheckpoint = 5", "[ner] checkpoint must be the path of a GLiNER checkpoint folder, not 5"),
    ("[ner.labels]\nCOLOUR = 'x'", "[ner.labels] has the key 'COLOUR', which must be one of VERB, WHAT"),
    ("[ner.labels]\nVERB = ['x']", "[ner.labels] VERB must be text on one line"),
    ('[ner.labels]\nVERB = "a\\nb"', "[ner.labels] VERB must be text on one line"),
    ("[translate]\nrepairs = 1.0", "[translate] repairs must be a whole number from 0 to 10, not 1.0"),
    ("[translate]\nground = 1", "[translate] ground must be true or false, not 1"),
    ("[translate]\nprimitives = [5]", "[translate] primitives[0] must be the path of a file, not 5"),
    ("[translate]\nprimitives = 'robot.toml'", "[translate] primitives must be a list of at most 50"),
    ("[translate]\nprimitives = ['']", "[translate] primitives[0] must be the path of a file, not ''"),
    ("keymap = 3", "keymap must be a table of binding ids and their keys"),
    ("[keymap]\ntranslate.run = 'f5'", "[keymap] translate must be text on one line"),
    ('[keymap]\n"translate.run" = "\\u0007"', "[keymap] 'translate.run' must be text on one line"),
    # unknown keys: refused, at every level, with the keys that are known there
    ("pages = 3", "unknown key pages (the file has ner, limits, translate, keymap)"),
    ("[limits]\npages = 3", "unknown key [limits] pages ([limits] has recipe_bytes, steps, llm_seconds)"),
    ("[ner]\nthreshhold = 0.4", "unknown key [ner] threshhold ([ner] has checkpoint, threshold, labels)"),
    ("[translate]\nrepair = 1", "unknown key [translate] repair ([translate] has primitives, repairs, ground, reuse)"),
])
def test_a_wrong_setting_names_the_file_the_key_and_what_it_must_be(tmp_path, content, expected):
    assert expected in refused(tmp_path, content)


@pytest.mark.parametrize("content, expected", [
    pytest.param("[ner]\ncheckpoint = '~no_such_user_here/gliner'", "[ner] checkpoint ~no_such_user_here/gliner: "
                 "cannot tell which home folder ~ means", id="unknown home"),
    pytest.param('[ner]\ncheckpoint = "a\\u0000b"', "is not a path (it holds a NUL byte", id="NUL"),
    pytest.param("[ner]\ncheckpoint = '" + "a" * 300 + "'", "is too long for a path", id="long name"),
    pytest.param("[translate]\nprimitives = ['" + "/abc" * 1024 + "']", "is too long for a path", id="long path"),
    pytest.param("[translate]\nprimitives = ['" + "/x" * 2100 + "']", "primitives[0] must be the path of a file",
                 id="longer path"),
    pytest.param("[translate]\nprimitives = [" + ", ".join(["'a.toml'"] * 51) + "]",
                 "primitives must be a list of at most 50", id="51 sets"),
    pytest.param("[keymap]\n" + "".join(f"k{i} = 'f1'\n" for i in range(201)), "keymap must be a table",
                 id="201 bindings"),
    pytest.param("x = " + "9" * 5000, "is not valid TOML: it holds a number too long to read", id="huge integer"),
    pytest.param("x = " + "[" * 5000, "is not valid TOML: it is nested too deeply", id="deep nesting"),
    pytest.param("[limits\n", "is not valid TOML: Expected ']'", id="syntax"),
])
def test_paths_counts_and_syntax_in_the_settings_are_bounded(tmp_path, content, expected):
    assert expected in refused(tmp_path, content)


def test_a_good_file_gives_typed_values_and_home_relative_paths(tmp_path, monkeypatch):
    monkeypatch.setenv("HOME", str(tmp_path))
    config = tmp_path / "settings.toml"
    config.write_text('[ner]\ncheckpoint = "~/gliner"\nthreshold = 1\n[ner.labels]\nverb = "action"\n'
                      '[limits]\nrecipe_bytes = 5000\nllm_seconds = 30\n'
                      '[translate]\nprimitives = ["~/arm.toml"]\nrepairs = 0\nground = false\nreuse = false\n'
                      '[keymap]\n"translate.run" = "f5"\n')
    settings = load_settings(config)
    assert settings.ner == NerSettings(tmp_path / "gliner", {Label.VERB: "action"}, 1.0)
    assert settings.limits == Limits(recipe_bytes=5000, steps=500, llm_seconds=30.0)
    assert type(settings.limits.llm_seconds) is float and type(settings.ner.threshold) is float
    assert settings.translate == TranslateSettings((tmp_path / "arm.toml",), 0, False, reuse=False)
    assert settings.keymap == {"translate.run": "f5"} and settings.source == config


def test_the_settings_api_is_unchanged():
    """What other modules build and replace: plain frozen dataclasses with class-level defaults."""
    assert TranslateSettings.repairs == 2 and TranslateSettings.ground is True and TranslateSettings.reuse is True
    assert Settings().limits == Limits() and Limits(recipe_bytes=10, steps=5).steps == 5
    replaced = dataclasses.replace(Settings(), ner=dataclasses.replace(NerSettings(), checkpoint=Path("/x")))
    assert replaced.ner.checkpoint == Path("/x")


def test_the_settings_path_itself_is_checked(tmp_path, monkeypatch):
    monkeypatch.setenv("HOME", str(tmp_path))
    (tmp_path / "mine.toml").write_text("[limits]\nsteps = 7\n")
    monkeypatch.setenv("COOK2LTL_CONFIG", "~/mine.toml")
    assert load_settings().limits.steps == 7
    monkeypatch.setenv("COOK2LTL_CONFIG", "/tmp/" + "x" * 300)
    with pytest.raises(UserError, match=r"\$COOK2LTL_CONFIG .* is too long for a path"):
        load_settings()
    monkeypatch.setenv("COOK2LTL_CONFIG", "/tmp/\udcff.toml")  # a byte that is not UTF-8, as the shell passed it
    with pytest.raises(UserError, match=r"\$COOK2LTL_CONFIG .* is not UTF-8"):
        load_settings()
    monkeypatch.setenv("COOK2LTL_CONFIG", str(tmp_path / "absent.toml"))
    assert load_settings() == Settings()  # no file: the defaults
