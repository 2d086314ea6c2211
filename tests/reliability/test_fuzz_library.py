"""Fuzzing targets: the action library's import, export, edit and open, on hostile files and paths.

Hostile exchange files (a good export mutated with wrong types, huge and special numbers, odd strings, markup
such as "[/nope]", control characters, lone surrogates; random JSON; bytes that are not JSON or not UTF-8),
hostile export targets (the library by another name, its -wal, another database, a FIFO, a device, a folder, a
link loop, long, NUL, ~), hostile body files and library files (random bytes, damaged copies of a library).
Whatever is thrown, the operation succeeds or raises a one-line UserError, never another exception; the library
then passes PRAGMA integrity_check and its approved entries are as they were. Each example runs in a fresh
temporary folder, which is also $HOME (so `~` stays inside it).
"""

from __future__ import annotations

import copy
import functools
import json
import os
import sqlite3
import stat
import tempfile
from contextlib import closing, contextmanager
from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st
from typer.testing import CliRunner

from cook2ltl.cli import app
from cook2ltl.errors import UserError
from cook2ltl.library import Library, Status
from cook2ltl.library.exchange import export_library, import_library
from cook2ltl.library.exchange_format import read_export
from tests.reliability.hostile import FUZZ, TRIED, hostile_text
from tests.reliability.test_library_files import approved_library

ODD_STRINGS = ("", " ", "[/nope]", "[bold red]x[/]", "\x1b[31mred", "\x00", "what,where", "$what", "$", "a" * 300,
               "pick_up($what)\nrm -rf /", "pick_up($what)", "boiled(what)", "ready(what)", "99999-01-01",
               "2026-13-45T25:61", "2026-01-01T00:00:00+00:00", "approved", "failed", "\ud800", "\u202eevil", "é",
               "🍳", "pick up", "PICK_UP", "9" * 30, "null", "NaN")
SPECIAL_NUMBERS = (0, 1, -1, 2, 2**31, 2**63 - 1, 2**63, -(2**63) - 1, 10**9, 10**9 + 1, 10**30, 10**4000,
                   0.5, 1.0, -0.0, 1e308, float("inf"), float("nan"))
scalars = st.one_of(st.none(), st.booleans(), st.integers(), st.sampled_from(SPECIAL_NUMBERS), st.floats(),
                    st.text(max_size=30), st.sampled_from(ODD_STRINGS), hostile_text)
values = st.recursive(scalars, lambda inner: st.lists(inner, max_size=4) | st.dictionaries(
    st.text(max_size=8) | st.sampled_from(["$what", "what", "version", "body"]), inner, max_size=4), max_leaves=10)


@functools.cache
def good_export() -> dict:
    """A real export of a small library: an approved entry with two versions and a review, a pending one that
    failed its kitchen check, a rejected one, one with no plan."""
    with tempfile.TemporaryDirectory() as folder:
        store = Library(Path(folder) / "source.sqlite")
        boil = store.add("recipe", "boil", ("what",), "pick_up($what)", "qwen", "h", validation="passed",
                         example={"$what": "egg"}, effect=["boiled(what)"])
        store.edit(boil.id, "pick_up($what)\nput($what, pot)", "bob", "passed")
        store.set_status(boil.id, Status.APPROVED, by="ann")
        store.add("recipe", "whisk", ("what", "where"), "stir($what)", "qwen", "h", validation="failed",
                  problems=["no whisk"])
        rinse = store.add("ai2thor", "rinse", (), "toggle_on(faucet)", "qwen", "h")
        store.set_status(rinse.id, Status.REJECTED, by="ann")
        store.add("recipe", "garnish", ("what",), "", "qwen", "h")
        export_library(store, Path(folder) / "good.json")
        store.close()
        return json.loads((Path(folder) / "good.json").read_text())


def places(value, at=()):
    """Every place in a JSON document: the path of keys and indexes to it."""
    yield at
    children = value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, list) else ()
    for key, item in children:
        yield from places(item, (*at, key))


@st.composite
def mutated_exports(draw) -> dict:
    """The good export with a few places replaced by hostile values, removed, or renamed to a new action."""
    document = copy.deepcopy(good_export())
    for _ in range(draw(st.integers(1, 3))):
        where = draw(st.sampled_from(list(places(document))))
        if not where:
            return draw(values)
        parent = functools.reduce(lambda node, key: node[key], where[:-1], document)
        how = draw(st.sampled_from(["replace", "remove", "new verb"]))
        if how == "remove":
            del parent[where[-1]]
        elif how == "new verb" and isinstance(parent, dict) and "verb" in parent:
            parent["verb"] = draw(st.from_regex(r"[a-z][a-z0-9_]{0,12}", fullmatch=True))
        else:
            parent[where[-1]] = draw(values)
    return document


@st.composite
def renamed_exports(draw) -> dict:
    """The good export as new actions (fresh verbs), its free text fields odd strings: mostly imported."""
    document = copy.deepcopy(good_export())
    free_text = st.sampled_from(ODD_STRINGS) | st.text(max_size=40)
    for entry in document["entries"]:
        entry["verb"] = draw(st.from_regex(r"[a-z][a-z0-9_]{0,12}", fullmatch=True))
        entry["model"] = draw(free_text)
        entry["history"][-1]["note"] = draw(free_text)
        entry["problems"] = draw(st.lists(free_text, max_size=2))
    return document


def as_bytes(document, ascii_only: bool) -> bytes:
    """JSON as a file holds it: escapes (\\ud800 stays an escape) or raw UTF-8 (a lone surrogate is then bytes
    that are not UTF-8)."""
    return json.dumps(document, ensure_ascii=ascii_only).encode("utf-8", "surrogatepass")


HAND_MADE_FILES = (b"", b"{", b"NaN", b"[]", b"\xef\xbb\xbf{}", b"\xff\xfe{\x00}\x00", b"[" * 100_000,
                   b'{"schema_version": 4, "entries": ' + b"[" * 5000 + b"]" * 5000 + b"}",
                   b'{"schema_version": 4, "entries": [' + b"{}," * 1000 + b"{}]}",
                   b'{"schema_version": 1' + b"0" * 5000 + b', "entries": []}', bytes(range(256)))
exchange_files = st.one_of(
    st.builds(as_bytes, mutated_exports(), st.booleans()),
    st.builds(as_bytes, renamed_exports(), st.booleans()),
    st.builds(as_bytes, values, st.booleans()),
    st.sampled_from(HAND_MADE_FILES),
    st.binary(max_size=200),
)


@contextmanager
def seeded():
    """A fresh folder (also $HOME) with a library: entry 1 approved, 2 pending, 3 rejected."""
    home = os.environ.get("HOME")
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        path = folder / "library.sqlite"
        approved_library(path)
        store = Library(path)
        rejected = store.add("ai2thor", "rinse", (), "toggle_on(faucet)", "m", "h")
        store.set_status(rejected.id, Status.REJECTED, by="ann")
        store.close()
        os.environ["HOME"] = name
        try:
            yield folder, path
        finally:
            if home is None:
                os.environ.pop("HOME")
            else:
                os.environ["HOME"] = home


def approved(path) -> list:
    """The approved entries, each with every version and review: what no failed operation may change."""
    with closing(sqlite3.connect(path)) as conn:
        return conn.execute(
            "SELECT a.*,"
            " (SELECT group_concat(v.version || ':' || v.body, '|') FROM versions v WHERE v.entry_id = a.id),"
            " (SELECT group_concat(r.version || r.status || r.reviewer, '|') FROM reviews r WHERE r.entry_id = a.id)"
            " FROM actions a WHERE a.status = 'approved' ORDER BY a.id").fetchall()


def dump(path) -> list[str]:
    with closing(sqlite3.connect(path)) as conn:
        return list(conn.iterdump())


def intact(path) -> None:
    with closing(sqlite3.connect(path)) as conn:
        assert conn.execute("PRAGMA integrity_check").fetchall() == [("ok",)]
        conn.execute("INSERT INTO actions_fts (actions_fts) VALUES ('integrity-check')")  # raises if out of step


def refused_clearly(error: UserError) -> None:
    assert error.message and "\n" not in error.message, repr(error.message)


@FUZZ
@given(exchange_files, st.booleans(), st.booleans())
def test_any_exchange_file_imports_or_is_refused_whole(document, replace_pending, force):
    TRIED["library import"] += 1
    with seeded() as (folder, path):
        (folder / "hostile.json").write_bytes(document)
        before, kept = dump(path), approved(path)
        store = Library(path)
        try:
            report = import_library(store, folder / "hostile.json", "fuzz", replace_pending, force)
        except UserError as error:
            refused_clearly(error)
            assert dump(path) == before
        else:
            assert all(store.history(e.id)[-1].body == e.body for e in store.entries())
            assert len(store.entries()) == 3 + len(report.added)
        finally:
            store.close()
        intact(path)
        assert approved(path)[:len(kept)] == kept  # an import adds approved entries, never changes one


NAME_CHARACTERS = st.characters(codec="utf-8", exclude_characters="/\x00")
names = st.one_of(st.text(NAME_CHARACTERS, min_size=1, max_size=40).filter(lambda n: n not in (".", "..")),
                  st.integers(250, 300).map(lambda n: "n" * n), st.sampled_from(["a\x00b", "-", " ", "~", "é"]))
TARGETS = ("library.sqlite", "library.sqlite-wal", "library.sqlite-shm", "link", "hard", "up/../library.sqlite",
           "other.sqlite", "fifo", "folder", "loop", "dangling", "device", "old.json", "old.json/child", "missing/x")


def hostile_folder(folder: Path) -> None:
    """What an export target may name, beside the library."""
    (folder / "link").symlink_to(folder / "library.sqlite")
    os.link(folder / "library.sqlite", folder / "hard")
    (folder / "up").mkdir()
    approved_library(folder / "other.sqlite")
    os.mkfifo(folder / "fifo")
    (folder / "folder").mkdir()
    (folder / "loop").symlink_to(folder / "loop")
    (folder / "dangling").symlink_to(folder / "nowhere.json")
    if os.geteuid() == 0:  # a device of our own (the null device's numbers): never /dev/null itself
        os.mknod(folder / "device", stat.S_IFCHR | 0o666, os.makedev(1, 3))
    (folder / "old.json").write_text("{}")


export_targets = st.one_of(
    st.sampled_from(TARGETS).map(lambda target: ("in", target)),
    names.map(lambda name: ("in", name)),
    st.lists(names, min_size=2, max_size=4).map(lambda parts: ("in", "/".join(parts))),
    st.integers(1, 2500).map(lambda n: ("in", "d/" * n + "x.json")),
    names.map(lambda name: ("home", f"~/{name}")),
)


@FUZZ
@given(export_targets)
def test_any_export_target_is_written_whole_or_refused_and_the_library_is_kept(target):
    TRIED["library export"] += 1
    with seeded() as (folder, path):
        hostile_folder(folder)
        where, name = target
        chosen = name if where == "home" else str(folder / name)
        before, others = dump(path), dump(folder / "other.sqlite")
        store = Library(path, read_only=True)
        try:
            count = export_library(store, chosen)
        except UserError as error:
            refused_clearly(error)
        else:
            written = Path(os.path.expanduser(chosen))
            assert count == 3 and len(read_export(written)) == 3
            assert written.resolve().is_relative_to(folder.resolve())
        finally:
            store.close()
        assert dump(path) == before and dump(folder / "other.sqlite") == others
        intact(path)
        assert stat.S_ISFIFO(os.stat(folder / "fifo").st_mode) and (folder / "folder").is_dir()
        assert not list(folder.rglob("*.tmp"))


body_files = st.one_of(hostile_text.map(lambda text: text.encode("utf-8", "surrogatepass")), st.binary(max_size=300),
                       st.sampled_from([b"stir($what)", b"pick_up($what)\nput($what, pot)", b"\xef\xbb\xbfstir($what)",
                                        b"stir($what)\n" * 2000, b"[/nope]", b"\x1b[2J", b"stir(\x00)"]))
body_sources = st.one_of(st.sampled_from(["file", "stdin", "/dev/zero", "fifo", "folder", "loop", "missing",
                                          "~/body.txt"]), names)


@FUZZ
@given(body_files, body_sources, st.sampled_from(["1", "2", "3", "99", str(2**63), "-1"]))
def test_any_body_file_is_stored_checked_or_refused(body, source, entry_id):
    TRIED["library edit"] += 1
    with seeded() as (folder, path):
        hostile_folder(folder)
        (folder / "body.txt").write_bytes(body)
        named = {"file": str(folder / "body.txt"), "stdin": "-", "/dev/zero": "/dev/zero", "~/body.txt": "~/body.txt"}
        chosen = named.get(source, str(folder / source))
        kept = approved(path)
        result = CliRunner().invoke(app, ["library", "edit", entry_id, "--body-file", chosen, "--no-validate",
                                          "--library", str(path), "--by", "fuzz"], input=body)
        if isinstance(result.exception, UserError):
            refused_clearly(result.exception)
        elif result.exception is not None:
            assert isinstance(result.exception, SystemExit) and result.exit_code in (1, 2), result.exception
        intact(path)
        if result.exit_code != 0 or entry_id != "1":  # a successful edit of entry 1 makes it pending, for review
            assert approved(path) == kept


def damaged(library: bytes, offsets: list[int], value: int) -> bytes:
    data = bytearray(library)
    for offset in offsets:
        data[offset % len(data)] = value
    return bytes(data)


library_files = st.one_of(
    st.binary(max_size=300),
    st.binary(max_size=300).map(lambda tail: b"SQLite format 3\x00" + tail),
    st.tuples(st.lists(st.integers(0, 2**20), min_size=1, max_size=8), st.integers(0, 255)),
)


@FUZZ
@given(library_files)
def test_any_library_file_opens_or_is_refused(content):
    TRIED["library open"] += 1
    with seeded() as (folder, path):
        hostile = folder / "hostile.sqlite"
        hostile.write_bytes(damaged(path.read_bytes(), *content) if isinstance(content, tuple) else content)
        try:
            store = Library(hostile)
            try:
                for entry in store.entries():
                    store.history(entry.id)
                    store.reviews(entry.id)
                store.search("boil")
                store.set_status(2, Status.APPROVED, by="fuzz")
            finally:
                store.close()
        except UserError as error:
            refused_clearly(error)
        intact(path)
