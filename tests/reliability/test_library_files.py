"""Hostile library files and import files: a clear error, exit code 2, and the library exactly as it was."""

import copy
import json
import os
import sqlite3
import subprocess
import sys

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cook2ltl.errors import UserError
from cook2ltl.library import Library, Status
from cook2ltl.library.exchange import export_library, import_library
from cook2ltl.library.schema import SCHEMA_VERSION
from tests.reliability.hostile import TRIED


def cook2ltl(*arguments: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "cook2ltl", *arguments], capture_output=True, text=True, timeout=120)


def assert_refused(result: subprocess.CompletedProcess, *words: str) -> None:
    assert result.returncode == 2 and "Traceback" not in result.stderr, result.stderr
    assert result.stderr.startswith("error: ")
    for word in words:
        assert word in result.stderr


def approved_library(path):
    store = Library(path)
    entry = store.add("recipe", "boil", ("what",), "pick_up($what)\nput($what, pot)", "m", "h",
                      example={"$what": "egg"})
    store.set_status(entry.id, Status.APPROVED, by="ann")
    store.add("recipe", "whisk", ("what",), "pick_up(whisk)\nstir($what)", "m", "h")
    store.close()


def library_state(path) -> list:
    with sqlite3.connect(path) as conn:
        return conn.execute("SELECT * FROM actions ORDER BY id").fetchall() + \
            conn.execute("SELECT * FROM versions ORDER BY entry_id, version").fetchall()


NOT_LIBRARIES = {
    "notes.sqlite": b"just some notes",
    "header-only.sqlite": b"SQLite format 3\x00" + b"\xff" * 200,
    "random.sqlite": bytes(range(256)) * 64,
}


@pytest.mark.parametrize("name", NOT_LIBRARIES)
def test_a_file_that_is_not_a_library_is_refused_and_left_as_it_was(tmp_path, name):
    TRIED["hand-made library file"] += 1
    path = tmp_path / name
    path.write_bytes(NOT_LIBRARIES[name])
    assert_refused(cook2ltl("library", "list", "--library", str(path)))
    assert path.read_bytes() == NOT_LIBRARIES[name]


def test_another_programs_sqlite_database_and_a_newer_schema_are_refused(tmp_path):
    other = tmp_path / "other.sqlite"
    with sqlite3.connect(other) as conn:
        conn.execute("CREATE TABLE invoices (id INTEGER)")
    before = other.read_bytes()
    assert_refused(cook2ltl("library", "list", "--library", str(other)), "not an action library")
    assert other.read_bytes() == before
    newer = tmp_path / "newer.sqlite"
    approved_library(newer)
    with sqlite3.connect(newer) as conn:
        conn.execute(f"PRAGMA user_version = {SCHEMA_VERSION + 1}")
    state = library_state(newer)
    assert_refused(cook2ltl("library", "list", "--library", str(newer)), f"schema version {SCHEMA_VERSION + 1}",
                   "upgrade cook2ltl")
    assert library_state(newer) == state
    TRIED["hand-made library file"] += 2


def test_a_folder_or_an_unwritable_place_as_library_is_a_clear_error(tmp_path):
    assert_refused(cook2ltl("library", "list", "--library", str(tmp_path)), "not a file")
    assert_refused(cook2ltl("library", "list", "--library", "/proc/cook2ltl/library.sqlite"))
    TRIED["hand-made library file"] += 2


@pytest.fixture(scope="module")
def good_export(tmp_path_factory):
    """A real export of a small library (so these tests follow the format as it evolves)."""
    folder = tmp_path_factory.mktemp("export")
    approved_library(folder / "source.sqlite")
    store = Library(folder / "source.sqlite")
    export_library(store, folder / "good.json")
    store.close()
    return json.loads((folder / "good.json").read_text())


HOSTILE_IMPORTS = {
    "not json": "{'schema_version': 3,",
    "a list": "[1, 2, 3]",
    "NaN": "NaN",
    "empty": "",
    "nested 100000 deep": "[" * 100_000 + "]" * 100_000,
    "huge number": '{"schema_version": 1' + "0" * 5000 + ', "entries": []}',
    "lone surrogate": None,  # built from the good export below
    "code as a body": None,
    "entries not a list": None,
}


def hostile_import(name: str, good: dict) -> str:
    if HOSTILE_IMPORTS[name] is not None:
        return HOSTILE_IMPORTS[name]
    bad = copy.deepcopy(good)
    entry = bad["entries"][0]
    if name == "lone surrogate":
        entry["verb"] = "bo\udcffil"
        return json.dumps(bad)  # ASCII JSON with a \\udcff escape: valid JSON, not encodable text
    if name == "code as a body":
        body = "__import__('os').system('touch pwned')"
        entry["body"] = body
        entry["history"][-1]["body"] = body
        return json.dumps(bad)
    bad["entries"] = {"0": entry}
    return json.dumps(bad)


def run_import(tmp_path, text: str) -> tuple[subprocess.CompletedProcess, list, list]:
    library = tmp_path / "library.sqlite"
    approved_library(library)
    state = library_state(library)
    (tmp_path / "import.json").write_text(text, errors="surrogatepass")
    result = cook2ltl("library", "import", str(tmp_path / "import.json"), "--library", str(library), "--by", "eve")
    return result, state, library_state(library)


@pytest.mark.parametrize("name", HOSTILE_IMPORTS)
def test_hostile_import_files_are_refused_and_the_library_is_unchanged(tmp_path, good_export, name):
    """(Deep nesting, a 5000-digit number and a lone surrogate were tracebacks until exchange.py 09c528f.)"""
    TRIED["hand-made import file"] += 1
    result, before, after = run_import(tmp_path, hostile_import(name, good_export))
    assert_refused(result)
    assert after == before
    assert not (tmp_path / "pwned").exists()


json_values = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=20),
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=8), inner, max_size=3),
    max_leaves=6)


def paths(value, prefix=()):
    yield prefix
    if isinstance(value, dict):
        for key, item in value.items():
            yield from paths(item, (*prefix, key))
    elif isinstance(value, list):
        for index, item in enumerate(value):
            yield from paths(item, (*prefix, index))


def mutated(document: dict, where: tuple, replacement, delete: bool):
    document = copy.deepcopy(document)
    if not where:
        return replacement
    parent = document
    for step in where[:-1]:
        parent = parent[step]
    if delete:
        del parent[where[-1]]
    else:
        parent[where[-1]] = replacement
    return document


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_any_mutation_of_an_export_imports_or_is_a_user_error_and_never_half_imports(tmp_path_factory, good_export,
                                                                                      data):
    TRIED["import mutations"] += 1
    where = data.draw(st.sampled_from(list(paths(good_export))))
    document = mutated(good_export, where, data.draw(json_values), data.draw(st.booleans()))
    folder = tmp_path_factory.mktemp("m")
    (folder / "import.json").write_text(json.dumps(document))
    store = Library(folder / "library.sqlite")
    try:
        before = store.entries()
        try:
            report = import_library(store, folder / "import.json", "eve")
        except UserError as error:
            assert error.message
            assert store.entries() == before  # refused as a whole: nothing written
            return
        assert len(store.entries()) == len(before) + len(report.added)
        for entry in store.entries():
            assert store.history(entry.id)[-1].body == entry.body
    finally:
        store.close()


@pytest.mark.parametrize("command", [["show"], ["approve"], ["reject"], ["history"], ["undo"],
                                     ["edit", "--body-file", "-"]])
@pytest.mark.parametrize("entry_id", [2**63, 2**70])
def test_an_entry_id_beyond_64_bits_is_a_clear_error(tmp_path, command, entry_id):
    approved_library(tmp_path / "library.sqlite")
    before = library_state(tmp_path / "library.sqlite")
    assert_refused(cook2ltl("library", command[0], str(entry_id), *command[1:],
                            "--library", str(tmp_path / "library.sqlite")), f"No entry {entry_id}")
    assert library_state(tmp_path / "library.sqlite") == before


@pytest.mark.parametrize("arguments, environment", [([b"list", b"--search", b"\xff"], {}),
                                                    ([b"approve", b"1", b"--by", b"\xff"], {}),
                                                    ([b"reject", b"1"], {b"COOK2LTL_USER": b"\xff"})])
def test_arguments_that_are_not_utf8_are_a_clear_error(tmp_path, arguments, environment):
    approved_library(tmp_path / "library.sqlite")
    result = subprocess.run([sys.executable.encode(), b"-m", b"cook2ltl", b"library", *arguments,
                             b"--library", str(tmp_path / "library.sqlite").encode()],
                            env={**os.environb, **environment}, capture_output=True, text=True, timeout=120)
    assert_refused(result, "not UTF-8")
    assert "\ufffd" in result.stderr or "COOK2LTL_USER" in result.stderr  # names what to fix
