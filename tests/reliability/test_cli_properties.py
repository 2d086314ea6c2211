"""The command line on arbitrary text: exit 0, or exit 2 with an "error:" message; never a traceback.

`main` runs in this process (sys.argv set, output captured) with the parsing backends and the model
replaced by fakes, so hundreds of inputs take seconds; test_cli_hostile.py runs the real thing.
"""

import contextlib
import io
import sys

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cook2ltl.cli import main
from tests.fakes import ScriptedDependencies
from tests.reduce.fake_model import ScriptedModel
from tests.reliability.hostile import TRIED, WordSpans, hostile_text

CLI = settings(max_examples=150, deadline=None,
               suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])


@pytest.fixture(scope="module")
def fake_backends():
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr("cook2ltl.assembly.backends.span_extractor", lambda settings: WordSpans())
        patch.setattr("cook2ltl.assembly.backends.dependency_parser", lambda: ScriptedDependencies())
        # Answers with a line for "boil", hostile text reaches the prompt of every other verb.
        patch.setattr("cook2ltl.assembly.backends.load_model", lambda name: ScriptedModel({"boil": "pick_up(pot)"}))
        yield


def run_cli(*argv: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    old_argv = sys.argv
    sys.argv = ["cook2ltl", *argv]
    code = 0
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            main()
    except SystemExit as exit_:
        code = exit_.code if isinstance(exit_.code, int) else 1
    finally:
        sys.argv = old_argv
    return code, out.getvalue(), err.getvalue()


def assert_clean(code: int, err: str) -> None:
    assert "Traceback" not in err
    assert code in (0, 2), (code, err)
    if code == 2:  # (translate's progress bar may leave an empty line first)
        assert err.lstrip("\n").startswith("error: "), err


@CLI
@given(st.one_of(st.text(max_size=80), hostile_text.filter(lambda t: len(t) < 400)))
def test_ltl_parse_any_text(text):
    TRIED["cli ltl parse"] += 1
    code, _, err = run_cli("ltl", "parse", "--", text)
    assert_clean(code, err)


@CLI
@given(hostile_text)
def test_parse_any_recipe_file(fake_backends, tmp_path_factory, text):
    TRIED["cli parse"] += 1
    path = tmp_path_factory.mktemp("r") / "recipe.txt"
    path.write_text(text, encoding="utf-8", errors="surrogatepass")
    for extra in ((), ("--json",)):
        code, _, err = run_cli("parse", str(path), *extra)
        assert_clean(code, err)


@CLI
@given(st.binary(max_size=300))
def test_parse_any_bytes(fake_backends, tmp_path_factory, data):
    TRIED["cli parse bytes"] += 1
    path = tmp_path_factory.mktemp("r") / "recipe.bin"
    path.write_bytes(data)
    code, _, err = run_cli("parse", str(path))
    assert_clean(code, err)


@settings(CLI, max_examples=60)
@given(hostile_text)
def test_translate_any_recipe_file(fake_backends, tmp_path_factory, text):
    TRIED["cli translate"] += 1
    folder = tmp_path_factory.mktemp("t")
    (folder / "recipe.txt").write_text(text, encoding="utf-8", errors="surrogatepass")
    code, _, err = run_cli("translate", str(folder / "recipe.txt"), "--library", str(folder / "library.sqlite"),
                           "--json")
    assert_clean(code, err)


@CLI
@given(st.text(max_size=40), st.lists(st.text(max_size=20), max_size=4), st.booleans())
def test_ltl_progress_any_formula_and_steps(formula, steps, as_json):
    TRIED["cli ltl progress"] += 1
    # "--" first: a step such as "-x" is text, not an option (a usage error is click's, not ours)
    code, _, err = run_cli("ltl", "progress", *(["--json"] if as_json else []), "--", formula, *steps)
    assert_clean(code, err)


@pytest.fixture(scope="module")
def small_library(tmp_path_factory):
    from cook2ltl.library import Library

    path = tmp_path_factory.mktemp("lib") / "library.sqlite"
    store = Library(path)
    store.add("recipe", "boil", ("what",), "pick_up($what)\nput($what, pot)", "m", "h")
    store.close()
    return str(path)


# Ids within SQLite's 64-bit integers here; larger ones are in test_library_files.py.
@CLI
@given(st.sampled_from(["show", "approve", "reject", "history", "undo"]),
       st.one_of(st.integers(-2**63, 2**63 - 1).map(str), st.text(max_size=12)), st.text(max_size=30))
def test_library_commands_on_any_id_and_search(small_library, command, entry_id, search):
    TRIED["cli library"] += 1
    code, _, err = run_cli("library", command, "--library", small_library, "--", entry_id)
    assert "Traceback" not in err
    if "Usage:" not in err:  # a non-number id is click's own usage error
        assert_clean(code, err)
    code, _, err = run_cli("library", "list", "--library", small_library, "--search", search)
    assert_clean(code, err)
