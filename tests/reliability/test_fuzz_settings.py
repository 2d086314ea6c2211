"""Fuzzing targets: hostile settings files, primitive-set files and paths.

Random TOML documents (any structure, any type, huge and special numbers, odd strings and keys, broken syntax,
bytes that are not UTF-8) and hostile paths (too long, NUL, not UTF-8, ~nobody, /dev/zero, a FIFO, a folder, a
symlink loop, a sparse 3 GB file) give a result within bounds or a one-line UserError, never another exception;
and nothing is written. Each example runs in a fresh temporary folder, which is also the working folder.
"""

from __future__ import annotations

import json
import math
import os
import re
import tempfile
from contextlib import contextmanager
from datetime import date, datetime, time
from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st

from cook2ltl import files, paths
from cook2ltl.cli.recipe_rollout import is_recipe
from cook2ltl.domain.recipe import Label
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.errors import UserError
from cook2ltl.preprocess.recipe_file import read_recipe
from cook2ltl.reduce.primitives import load_primitives
from tests.reliability.hostile import FUZZ, TRIED

IDENTIFIER = re.compile(r"[a-z][a-z0-9_]*\Z")
ODD_STRINGS = ("", " ", "~", "~/", "~no_such_user_here/x", "/dev/zero", "/dev/stdin", "/proc/self/mem", "a" * 300,
               "/tmp/" + "a/" * 2500, "[bold]x[/bold]", "\u202eevil", "a\x00b", "\x1b[2J", "../../etc/passwd",
               "VERB", "verb", "f5", "ctrl+r", "y,a", "translate.run", "pick up", "pick_up", "what", "condition",
               "thor", "e.txt", "d.pddl", "big", "fifo", "loop", "folder", "é", "🍳", "\ud800", "9" * 30)
SPECIAL_NUMBERS = (0, 1, -1, 2, 10, 11, 2**63 - 1, -(2**63), 10**30, 0.5, 1.0, -0.0, 1e300, -1e300, 5e-324,
                   math.inf, -math.inf, math.nan, 100_000, 100_001, 10_000_000, 10_000_001, 3600, 3600.5)
SETTING_KEYS = ("ner", "limits", "translate", "keymap", "checkpoint", "threshold", "labels", "recipe_bytes", "steps",
                "llm_seconds", "primitives", "repairs", "ground", "reuse", "VERB", "what", "TEMP", "translate.run")
SET_KEYS = ("name", "examples", "objects", "states", "primitives", "world", "domain", "kitchen", "kit", "planner",
            "liquids", "put", "wait", "pick_up", "what", "where", "condition", "boiled", "*")

scalars = st.one_of(
    st.booleans(), st.integers(), st.sampled_from(SPECIAL_NUMBERS), st.floats(), st.text(max_size=30),
    st.sampled_from(ODD_STRINGS), st.dates(), st.datetimes(), st.times(),
)
values = st.recursive(scalars, lambda inner: st.lists(inner, max_size=4) | st.dictionaries(
    st.text(max_size=8), inner, max_size=4), max_leaves=12)


def tables(known: tuple[str, ...]):
    keys = st.one_of(st.sampled_from(known), st.text(min_size=1, max_size=10))
    return st.dictionaries(keys, st.one_of(values, st.dictionaries(keys, values, max_size=4)), max_size=5)


def toml_value(value) -> str:
    """A value as TOML (inline tables for tables); what TOML cannot say comes out invalid, which is a case too."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf") if math.isinf(value) else repr(value)
    if isinstance(value, (int, str)):
        return json.dumps(value, ensure_ascii=False) if isinstance(value, str) else str(value)
    if isinstance(value, (date, datetime, time)):
        return value.isoformat()
    if isinstance(value, list):
        return "[" + ", ".join(map(toml_value, value)) + "]"
    return "{" + ", ".join(f"{json.dumps(k, ensure_ascii=False)} = {toml_value(v)}" for k, v in value.items()) + "}"


def toml_document(document: dict) -> str:
    """Keys with plain values first, then each table under its own [header]."""
    lines = [f"{json.dumps(k, ensure_ascii=False)} = {toml_value(v)}" for k, v in document.items()
             if not isinstance(v, dict)]
    for key, table in document.items():
        if isinstance(table, dict):
            lines.append(f"[{json.dumps(key, ensure_ascii=False)}]")
            lines += [f"{json.dumps(k, ensure_ascii=False)} = {toml_value(v)}" for k, v in table.items()]
    return "\n".join(lines) + "\n"


def broken(documents):
    """A document as it is (most often), cut with noise put in, or as bytes that need not be UTF-8."""
    text = documents.map(toml_document)
    whole = text.map(lambda t: t.encode("utf-8", "surrogatepass"))
    return st.one_of(
        whole, whole, whole,
        st.tuples(text, st.integers(0, 400), st.text(max_size=10)).map(lambda t: (t[0][:t[1]] + t[2] + t[0][t[1]:])
                                                                       .encode("utf-8", "surrogatepass")),
        st.binary(max_size=300),
        st.sampled_from([b"x = " + b"9" * 5000, b"x = " + b"[" * 3000, b"\xef\xbb\xbf[limits]\nsteps = 5\n"]),
    )


def table_of(keys: tuple[str, ...], value=values):
    """A table with some of `keys` and now and then another key."""
    table = st.fixed_dictionaries({}, optional={key: value for key in keys})
    extra = st.dictionaries(st.text(min_size=1, max_size=8), values, max_size=1)
    return st.one_of(table, table, table, st.tuples(table, extra).map(lambda t: {**t[0], **t[1]}))


def or_not_a_table(tables_):
    return st.one_of(tables_, tables_, tables_, values)


def with_labels(ner: dict) -> dict:
    """Mostly a label the checkpoint knows, so the other labels are checked too."""
    return {**ner, "labels": {"VERB": "action", **ner["labels"]}} if isinstance(ner.get("labels"), dict) else ner


names = st.one_of(st.sampled_from(ODD_STRINGS), st.from_regex(r"[a-z][a-z0-9_]{0,8}", fullmatch=True),
                  st.text(max_size=8))
settings_files = st.one_of(
    st.fixed_dictionaries({}, optional={
        "ner": or_not_a_table(table_of(("checkpoint", "threshold", "labels")).map(with_labels)),
        "limits": or_not_a_table(table_of(("recipe_bytes", "steps", "llm_seconds"),
                                          st.sampled_from(SPECIAL_NUMBERS) | values)),
        "translate": or_not_a_table(table_of(("primitives", "repairs", "ground", "reuse"))),
        "keymap": or_not_a_table(st.dictionaries(names, names | values, max_size=4)),
    }),
    tables(SETTING_KEYS),
)


@contextmanager
def scratch_folder(document: bytes = b""):
    """A fresh working folder holding the document (doc.toml) and the hostile files a path may name; fails if
    anything in it changed when the example is done."""
    before = os.getcwd()
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        os.mkfifo(folder / "fifo")  # nobody writes: opening it to read would wait forever
        (folder / "folder").mkdir()
        (folder / "loop").symlink_to(folder / "loop")
        with (folder / "big").open("wb") as handle:
            handle.truncate(3 * 2**30)  # sparse: no disk used
        (folder / "e.txt").write_text("def boil(water: what):\n    put(water, pot)\n")
        (folder / "d.pddl").write_text("(define (domain d))\n")
        (folder / "doc.toml").write_bytes(document)
        at_start = _listing(folder)
        os.chdir(folder)
        try:
            yield folder
        finally:
            os.chdir(before)
        assert _listing(folder) == at_start, "a file was written"


def _listing(folder: Path) -> dict[str, tuple[int, int, int]]:
    found = {}
    for root, dirs, names in os.walk(folder):
        for name in dirs + names:
            status = (Path(root) / name).lstat()
            found[str(Path(root, name).relative_to(folder))] = (status.st_mode, status.st_size, status.st_mtime_ns)
    return found


def refused_clearly(error: UserError) -> None:
    assert error.message and "\n" not in error.message, repr(error.message)


@FUZZ
@given(broken(settings_files))
def test_any_settings_file_gives_bounded_settings_or_a_user_error(document):
    TRIED["settings file"] += 1
    with scratch_folder(document) as folder:
        try:
            settings = load_settings(folder / "doc.toml")
        except UserError as error:
            refused_clearly(error)
            return
    limits, translate, ner = settings.limits, settings.translate, settings.ner
    assert type(limits.recipe_bytes) is int and 1 <= limits.recipe_bytes <= 10_000_000
    assert type(limits.steps) is int and 1 <= limits.steps <= 100_000
    assert type(limits.llm_seconds) is float and 1 <= limits.llm_seconds <= 3600
    assert type(ner.threshold) is float and 0 <= ner.threshold <= 1
    assert type(translate.repairs) is int and 0 <= translate.repairs <= 10 and type(translate.ground) is bool
    assert type(translate.reuse) is bool
    assert all(isinstance(label, Label) and isinstance(name, str) for label, name in ner.labels.items())
    assert all(isinstance(path, Path) for path in translate.primitives)
    assert all(isinstance(k, str) and isinstance(v, str) for k, v in settings.keymap.items())


GOOD_SET = {"name": "arm", "examples": "e.txt", "objects": ["pot", "stovetop"], "states": ["boiled"],
            "primitives": {"put": ["what", "where"], "wait": ["condition"]}}


def mutated_sets():
    """The good set with some keys replaced by hostile values, tables of hostile primitives, a hostile [world]."""
    primitives = st.dictionaries(names, st.one_of(st.lists(names, max_size=3), values), min_size=1, max_size=4)
    world = or_not_a_table(table_of(("domain", "kitchen", "kit", "planner", "liquids", "states")).map(
        lambda t: {"domain": "d.pddl", **t}))
    changes = st.fixed_dictionaries({}, optional={
        "name": st.sampled_from(["arm", "my-robot", "Arm.2"]) | names | values, "examples": st.sampled_from(ODD_STRINGS) | values,
        "objects": st.lists(names, max_size=4) | values, "states": st.lists(names, max_size=4) | values,
        "primitives": primitives | values, "world": world})
    return st.one_of(changes.map(lambda c: {**GOOD_SET, **c}), tables(SET_KEYS))


@FUZZ
@given(broken(mutated_sets()))
def test_any_primitive_set_file_gives_a_checked_set_or_a_user_error(document):
    TRIED["primitive set file"] += 1
    with scratch_folder(document) as folder:
        try:
            chosen = load_primitives(str(folder / "doc.toml"))
        except UserError as error:
            refused_clearly(error)
            return
    words = [*chosen.objects, *chosen.states, *(p.name for p in chosen.primitives),
             *(param for p in chosen.primitives for param in p.params)]
    assert all(IDENTIFIER.match(word) and len(word) <= 64 for word in words)  # safe to splice into a grammar
    assert 1 <= len(chosen.primitives) <= 200 and len(chosen.objects) <= 2000 and len(chosen.states) <= 500
    assert isinstance(chosen.examples, str)


PATH_PIECES = ("~", "/", "..", ".", "a", "é", "\x00", "\udcff", "\n", " ", "*", "$HOME", "fifo", "loop", "folder",
               "big", "e.txt", "-", "\\", "'", '"', "\u202e", "x" * 255, "y" * 256)
hostile_paths = st.one_of(
    st.sampled_from(ODD_STRINGS), st.text(max_size=30),
    st.integers(200, 6000).map(lambda n: "p" * n),
    st.integers(1, 3000).map(lambda n: "/tmp/" + "b/" * n),
    st.lists(st.sampled_from(PATH_PIECES), max_size=10).map("".join),
)


@FUZZ
@given(hostile_paths)
def test_any_path_is_read_within_bounds_or_refused(path):
    TRIED["paths"] += 1
    readers = [lambda: paths.user_path(path, "The path"),
               lambda: files.read_text(paths.user_path(path, "The path"), 1000, "file", "give another"),
               lambda: load_settings(path), lambda: load_primitives(path)]
    if path != "-":  # `-` is standard input, which pytest does not let a test read
        readers.append(lambda: read_recipe(path, 1000))
    with scratch_folder():
        for read in readers:
            try:
                read()
            except UserError as error:
                refused_clearly(error)
        assert is_recipe(path) in (True, False)
        if _environment_can_hold(path):
            _config_from_environment(path)


def _environment_can_hold(path: str) -> bool:
    """No NUL, and nothing the file system's encoding cannot give back as bytes (a lone \\ud800)."""
    try:
        return b"\x00" not in os.fsencode(path)
    except UnicodeEncodeError:
        return False


def _config_from_environment(path: str) -> None:
    saved = os.environ.get("COOK2LTL_CONFIG")
    os.environ["COOK2LTL_CONFIG"] = path
    try:
        load_settings()
    except UserError as error:
        refused_clearly(error)
    finally:
        if saved is None:
            del os.environ["COOK2LTL_CONFIG"]
        else:
            os.environ["COOK2LTL_CONFIG"] = saved
