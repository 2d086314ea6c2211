"""Every path a user gives (an option, an argument, a setting, a $COOK2LTL_* variable): `~` expanded the same
way everywhere, and a path no system call could take (too long, a NUL, not UTF-8, ~nobody) a one-line
UserError naming where it came from; through the real command line too, exit code 2 and no traceback."""

import os
import subprocess
import sys
from pathlib import Path

import pytest

from cook2ltl import paths
from cook2ltl.cli.recipe_rollout import is_recipe
from cook2ltl.errors import UserError
from cook2ltl.preprocess.recipe_file import read_recipe
from cook2ltl.reduce.primitives import load_primitives

HOSTILE = {
    "5000 characters": ("/tmp/" + "a/" * 2500, "is too long for a path"),
    "a 300-byte name": ("/tmp/" + "é" * 150, "is too long for a path"),
    "NUL": ("/tmp/a\x00b", "holds a NUL byte"),
    "not UTF-8": ("/tmp/\udcff\udcfe", "is not UTF-8"),
    "unknown home": ("~no_such_user_here/x", "cannot tell which home folder ~ means"),
    "empty": ("  ", "is empty"),
}


@pytest.mark.parametrize("name", HOSTILE)
def test_a_path_no_system_call_could_take_is_refused_by_name(name):
    value, message = HOSTILE[name]
    with pytest.raises(UserError, match="--library") as raised:
        paths.user_path(value, "--library")
    assert message in raised.value.message and "\n" not in raised.value.message


@pytest.mark.parametrize("name", HOSTILE)
def test_every_reader_of_a_user_path_refuses_it_clearly(name, tmp_path):
    value, message = HOSTILE[name]
    for read in (lambda: read_recipe(value, 1000), lambda: load_primitives(value),
                 lambda: paths.output_folder(value, "--pddl")):
        with pytest.raises(UserError, match=message):
            read()
    assert is_recipe(value) is False  # a rollout target that is no file is a task or a formula


@pytest.mark.parametrize("variable, function", [
    ("COOK2LTL_CONFIG", paths.config_file), ("COOK2LTL_LIBRARY", paths.library_file),
    ("COOK2LTL_ASSETS", paths.assets_dir), ("COOK2LTL_MODELS_DIR", paths.models_dir),
    ("COOK2LTL_MODEL_CACHE", paths.model_cache_dir), ("COOK2LTL_DATA", paths.data_dir),
])
def test_environment_paths_expand_home_and_are_checked(monkeypatch, tmp_path, variable, function):
    monkeypatch.setenv("HOME", str(tmp_path))
    monkeypatch.setenv(variable, "~/here")
    assert function() == tmp_path / "here"
    monkeypatch.setenv(variable, "/tmp/" + "x" * 300)
    with pytest.raises(UserError, match=rf"\${variable} .* is too long"):
        function()


def test_home_relative_paths_are_expanded_for_recipes_and_sets(monkeypatch, tmp_path):
    monkeypatch.setenv("HOME", str(tmp_path))
    (tmp_path / "recipe.txt").write_text("Boil the eggs.")
    assert read_recipe("~/recipe.txt", 1000) == "Boil the eggs." and is_recipe("~/recipe.txt")
    assert paths.output_folder("~/out/pddl", "--pddl") == tmp_path / "out" / "pddl"
    assert (tmp_path / "out" / "pddl").is_dir()


def test_an_output_folder_that_cannot_be_one_is_refused_before_the_run(tmp_path):
    (tmp_path / "file").write_text("x")
    for folder in (tmp_path / "file", tmp_path / "file" / "below"):
        with pytest.raises(UserError, match="--out .* cannot be a folder to write into"):
            paths.output_folder(folder, "--out")


def test_a_long_formula_is_no_file_name():
    assert is_recipe("F(" + " & ".join(["pick_up(apple)"] * 40) + ")") is False


def cook2ltl(tmp_path: Path, *arguments: str, **env: str) -> subprocess.CompletedProcess:
    environment = {**os.environ, "COOK2LTL_CONFIG": str(tmp_path / "absent.toml"),
                   "COOK2LTL_LIBRARY": str(tmp_path / "library.sqlite"), **env}
    return subprocess.run([sys.executable, "-m", "cook2ltl", *arguments], capture_output=True, timeout=300,
                          env=environment, cwd=tmp_path)


LONG_NAME = "x" * 300


@pytest.mark.parametrize("case, arguments, environment, message", [
    ("recipe at /dev/zero", ["parse", "/dev/zero"], {}, "not a regular file"),
    ("recipe path too long", ["parse", "/tmp/" + "a/" * 2500], {}, "is too long for a path"),
    ("recipe under a file", ["parse", "recipe.txt/x"], {}, "Not a directory"),
    ("settings at /dev/zero", ["parse", "recipe.txt"], {"COOK2LTL_CONFIG": "/dev/zero"}, "settings file /dev/zero"),
    ("settings of the wrong type", ["parse", "recipe.txt"], {"COOK2LTL_CONFIG": "bad.toml"},
     "[limits] steps must be a whole number from 1 to 100,000, not 0.5"),
    ("primitives at /dev/zero", ["translate", "recipe.txt", "--primitives", "/dev/zero"], {}, "primitive set"),
    ("library name too long", ["translate", "recipe.txt", "--library", f"/tmp/{LONG_NAME}"], {}, "--library"),
    ("library list, name too long", ["library", "list", "--library", f"~/{LONG_NAME}"], {}, "--library"),
    ("pddl under a file", ["translate", "recipe.txt", "--pddl", "recipe.txt/pddl"], {},
     "--pddl recipe.txt/pddl cannot be a folder to write into"),
    ("bench out is a file", ["bench", "micro", "--out", "recipe.txt"], {}, "--out recipe.txt cannot be a folder"),
    ("formula too long for a path", ["rollout", "G(" + "a" * 300], {}, "is neither a task nor a formula"),
])
def test_the_command_line_refuses_bad_paths_in_one_line(tmp_path, case, arguments, environment, message):
    (tmp_path / "recipe.txt").write_text("Boil the eggs.")
    (tmp_path / "bad.toml").write_text("[limits]\nsteps = 0.5\n")
    result = cook2ltl(tmp_path, *arguments, **environment)
    err = result.stderr.decode()
    assert result.returncode == 2 and "Traceback" not in err, err
    assert err.startswith("error: ") and message in " ".join(err.split()), err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml", "recipe.txt"]  # nothing written


def test_the_kitchens_paths_from_the_environment_are_checked_too(monkeypatch):
    """$COOK2LTL_ASSETS as the kitchens read it, $COOK2LTL_THOR_EXECUTABLE and $COOK2LTL_KITCHEN_CACHE: a path
    too long or holding raw bytes is a clear refusal, never a traceback."""
    from cook2ltl.errors import UserError
    from cook2ltl.execution import launcher
    from cook2ltl.simulator import scenes

    long = "/" + "x" * 300
    monkeypatch.setenv("COOK2LTL_ASSETS", long)
    with pytest.raises(UserError, match="COOK2LTL_ASSETS .* too long"):
        scenes.kitchens_dir()
    monkeypatch.delenv("COOK2LTL_ASSETS")
    monkeypatch.setenv(launcher.THOR_EXECUTABLE_ENV, long)
    with pytest.raises(launcher.KitchenUnavailable, match="too long"):
        launcher.find_thor_build()
    monkeypatch.setenv("COOK2LTL_KITCHEN_CACHE", "~nobody-of-that-name/cache")
    with pytest.raises(UserError, match="COOK2LTL_KITCHEN_CACHE"):
        launcher._cache_dir()


def test_a_lone_surrogate_is_refused_clearly():
    from cook2ltl.errors import UserError, require_utf8

    with pytest.raises(UserError, match=r"'x\\\\ud800y' is not UTF-8"):
        require_utf8("x\ud800y", "name", "hint")
