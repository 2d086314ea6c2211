"""Issue 16, the action library's files: an export never destroys the library or anything but a regular file and
is written whole; a locked, full, read-only or damaged library is said to be just that (never "move that file
away"); reads never wait for another process's write; every file read is bounded; odd paths are clear errors."""

import json
import os
import sqlite3
import stat
import subprocess
import sys
import time

import pytest
from sqlite_utils import Database

from cook2ltl.errors import UserError
from cook2ltl.library import Library, Status, connection
from cook2ltl.library.exchange import export_library, import_library
from cook2ltl.library.schema import MIGRATIONS
from tests.reliability.test_library_files import approved_library, assert_refused, library_state

MOVE_AWAY = "move that file away"


def cook2ltl(*arguments: str, **environment: str) -> subprocess.CompletedProcess:
    """The command line, its messages on one line each (a wide terminal) so the tests can look for words."""
    return subprocess.run([sys.executable, "-m", "cook2ltl", *arguments], capture_output=True, text=True,
                          timeout=120, env={**os.environ, "COLUMNS": "1000", **environment})


def intact(path) -> None:
    with sqlite3.connect(path) as conn:
        assert conn.execute("PRAGMA integrity_check").fetchall() == [("ok",)]


@pytest.fixture
def library(tmp_path):
    path = tmp_path / "library.sqlite"
    approved_library(path)
    return path


# --- export -----------------------------------------------------------------------------------------------------

def library_names(tmp_path, library) -> dict:
    (tmp_path / "link.sqlite").symlink_to(library)
    os.link(library, tmp_path / "hard.sqlite")
    return {"itself": str(library), "a symlink": str(tmp_path / "link.sqlite"),
            "a hard link": str(tmp_path / "hard.sqlite"), "its -wal": f"{library}-wal", "its -shm": f"{library}-shm",
            "the folder, then ..": str(tmp_path / "." / ".." / tmp_path.name / library.name)}


@pytest.mark.parametrize("name", ["itself", "a symlink", "a hard link", "its -wal", "its -shm", "the folder, then .."])
def test_export_onto_the_library_by_any_name_is_refused_and_loses_nothing(tmp_path, library, name):
    """(`library export "$COOK2LTL_LIBRARY"` exited 0 and left a file that was neither library nor export.)"""
    target = library_names(tmp_path, library)[name]
    before = library_state(library)
    result = cook2ltl("library", "export", target, COOK2LTL_LIBRARY=str(library))
    assert_refused(result, "it is the action library")
    assert MOVE_AWAY not in result.stderr
    intact(library)
    assert library_state(library) == before
    assert_refused(cook2ltl("library", "export", target, "--library", str(library)))  # --library: the same


def test_export_replaces_only_a_regular_file_that_is_no_sqlite_database(tmp_path, library):
    other = tmp_path / "other.sqlite"
    approved_library(other)
    fifo, folder = tmp_path / "fifo", tmp_path / "folder"
    os.mkfifo(fifo)
    folder.mkdir()
    targets = {str(other): "an SQLite database", str(fifo): "a FIFO", str(folder): "a folder"}
    if os.geteuid() == 0:  # a device node of our own: /dev/null itself is never put at risk
        os.mknod(tmp_path / "null", stat.S_IFCHR | 0o666, os.makedev(1, 3))
        targets[str(tmp_path / "null")] = "a device"
    before = library_state(other)
    for target, kind in targets.items():
        assert_refused(cook2ltl("library", "export", target, "--library", str(library)), kind)
    assert library_state(other) == before and stat.S_ISFIFO(os.stat(fifo).st_mode) and folder.is_dir()
    old = tmp_path / "old.json"
    old.write_text("{}")
    old.chmod(0o640)
    assert cook2ltl("library", "export", str(old), "--library", str(library)).returncode == 0
    assert len(json.loads(old.read_text())["entries"]) == 2 and stat.S_IMODE(old.stat().st_mode) == 0o640


@pytest.mark.parametrize("failing", ["fsync", "replace", "interrupt"])
def test_an_export_that_fails_half_way_leaves_the_old_file_and_no_temporary_one(tmp_path, library, monkeypatch,
                                                                                 failing):
    target = tmp_path / "lab.json"
    target.write_text('{"old": true}')
    store = Library(library, read_only=True)

    def fail(*_):
        raise KeyboardInterrupt if failing == "interrupt" else OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace" if failing != "fsync" else "fsync", fail)
    with pytest.raises(KeyboardInterrupt if failing == "interrupt" else UserError):
        export_library(store, target)
    store.close()
    assert target.read_text() == '{"old": true}'
    assert not [p.name for p in tmp_path.iterdir() if p.name.endswith(".tmp")]


# --- locks, a full disk, a read-only or damaged file ---------------------------------------------------------------

HOLDER = """
import sqlite3, sys
conn = sqlite3.connect(sys.argv[1], isolation_level=None)
conn.execute("BEGIN IMMEDIATE")
conn.execute("INSERT INTO actions (primitives, verb, signature, body, model, prompt_hash, created) "
             "VALUES ('recipe', 'half', 'what', 'stir($what)', 'm', 'h', 'now')")
print("locked", flush=True)
sys.stdin.readline()
conn.execute("ROLLBACK")
"""


@pytest.fixture
def locked(library):
    """The library with another process in the middle of a long write (as a large import is)."""
    holder = subprocess.Popen([sys.executable, "-c", HOLDER, str(library)], stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, text=True)
    assert holder.stdout.readline().strip() == "locked"
    yield library
    holder.communicate("\n", timeout=30)


def test_reading_commands_never_wait_for_another_processs_write(tmp_path, locked):
    """(Every open migrated under BEGIN IMMEDIATE: `library list` failed after 10 s during an import.)"""
    for command in (["list"], ["show", "1"], ["history", "1"], ["export", str(tmp_path / "out.json")]):
        started = time.monotonic()
        result = cook2ltl("library", *command, "--library", str(locked))
        assert result.returncode == 0, result.stderr
        assert time.monotonic() - started < 8  # the busy timeout is 10 s: it did not wait for the lock
    assert "half" not in cook2ltl("library", "list", "--library", str(locked)).stdout  # never half a write
    assert len(json.loads((tmp_path / "out.json").read_text())["entries"]) == 2


def test_a_write_that_outwaits_the_lock_says_it_is_locked(tmp_path, locked, monkeypatch):
    """(The pipeline's add and lookup raised `database is locked` through `translate`.)"""
    monkeypatch.setattr(connection, "BUSY_TIMEOUT_MS", 200)
    store = Library(locked)
    for write in (lambda: store.set_status(2, Status.APPROVED, by="ann"),
                  lambda: store.add("recipe", "fry", ("what",), "put($what, pan)", "m", "h"),
                  lambda: store.edit(2, "stir($what)", "ann"), lambda: store.undo(2, "ann"),
                  lambda: import_library(store, export_of(tmp_path, locked), "eve")):
        with pytest.raises(UserError, match="is locked: another cook2ltl process is writing to it") as raised:
            write()
        assert MOVE_AWAY not in str(raised.value) and "try again" in raised.value.hint
    assert [e.verb for e in store.entries()] == ["boil", "whisk"]  # reads go on meanwhile
    store.close()


def export_of(tmp_path, library):
    store = Library(library, read_only=True)
    export_library(store, tmp_path / "export.json")
    store.close()
    data = json.loads((tmp_path / "export.json").read_text())
    data["entries"][0]["verb"] = "poach"  # a new entry, so the import has something to write
    (tmp_path / "export.json").write_text(json.dumps(data))
    return tmp_path / "export.json"


def test_an_older_library_locked_by_another_process_is_said_to_be_locked(tmp_path, monkeypatch):
    path = tmp_path / "old.sqlite"
    conn = sqlite3.connect(path, isolation_level=None)
    MIGRATIONS[0](Database(conn))  # a library of schema version 1, which opening must migrate
    conn.execute("PRAGMA user_version = 1")
    conn.execute("BEGIN IMMEDIATE")
    monkeypatch.setattr(connection, "BUSY_TIMEOUT_MS", 200)
    with pytest.raises(UserError, match="is locked") as raised:
        Library(path)
    assert MOVE_AWAY not in str(raised.value)
    conn.execute("ROLLBACK")
    conn.close()
    Library(path).close()  # once the lock is gone, it migrates


def test_a_full_disk_is_said_to_be_full_and_writes_nothing(library):
    store = Library(library)
    before = library_state(library)
    conn = store._db().conn
    conn.execute(f"PRAGMA max_page_count = {conn.execute('PRAGMA page_count').fetchone()[0]}")  # no page more
    with pytest.raises(UserError, match="is full; nothing was written") as raised:
        for number in range(200):
            store.add("recipe", f"verb_{number}", ("what",), "stir($what)\n" * 200, "m", "h")
    assert MOVE_AWAY not in str(raised.value)
    store.close()
    intact(library)
    assert library_state(library)[:2] == before[:2]  # both entries as they were


def test_a_read_only_library_is_said_to_be_read_only(library):
    store = Library(library)
    store._db().conn.execute("PRAGMA query_only = 1")  # as a read-only file or mount refuses writes
    with pytest.raises(UserError, match="is read-only; nothing was written") as raised:
        store.set_status(2, Status.APPROVED, by="ann")
    assert MOVE_AWAY not in str(raised.value)
    store.close()
    reader = Library(library, read_only=True)
    with pytest.raises(UserError, match="is read-only"):
        reader.edit(2, "stir($what)", "ann")
    reader.close()


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes to read-only files")
def test_a_read_only_file_and_folder_can_be_read_but_not_written(library):
    Library(library).close()
    library.chmod(0o444)
    library.parent.chmod(0o555)
    try:
        assert cook2ltl("library", "list", "--library", str(library)).returncode == 0
        result = cook2ltl("library", "approve", "2", "--library", str(library))
        assert_refused(result, "read-only")
        assert MOVE_AWAY not in result.stderr
    finally:
        library.parent.chmod(0o755)
        library.chmod(0o644)


def test_a_damaged_library_is_said_to_be_damaged_and_only_a_foreign_file_is_not_a_library(tmp_path, library):
    data = library.read_bytes()
    library.write_bytes(data[:4096] + b"\xff" * (len(data) - 4096))  # every page but the first: still SQLite's
    for command in (["list"], ["show", "1"], ["export", str(tmp_path / "out.json")], ["approve", "2"]):
        result = cook2ltl("library", *command, "--library", str(library))
        assert_refused(result, "is damaged")
        assert MOVE_AWAY not in result.stderr
    foreign = tmp_path / "notes.sqlite"
    foreign.write_bytes(b"some notes, not a database" * 100)
    assert_refused(cook2ltl("library", "list", "--library", str(foreign)), "is not an action library", MOVE_AWAY)


@pytest.mark.parametrize("damage", [
    "PRAGMA user_version = -3",  # a schema version no cook2ltl writes
    "DROP TABLE actions_fts",  # the search index gone
    "UPDATE actions SET version = 'seven', verb = 7 WHERE id = 1",  # a row's columns of the wrong type
])
def test_damage_the_fuzzer_found_is_said_to_be_damage(library, damage):
    """(Found by `cook2ltl bench fuzz`: IndexError, ValueError, TypeError and AttributeError from damaged files.)"""
    with sqlite3.connect(library) as conn:
        conn.executescript(damage)
    with pytest.raises(UserError, match="is damaged"):
        store = Library(library)
        try:
            store.entries()
            store.search("boil")
        finally:
            store.close()


# --- bounded reads -----------------------------------------------------------------------------------------------

def test_endless_or_special_files_are_refused_before_they_are_read(tmp_path, library):
    """(`library edit 2 --body-file /dev/zero` and `library import /dev/zero` grew until memory ran out.)"""
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)  # nobody writes: opening it for reading would wait forever
    before = library_state(library)
    for special in ("/dev/zero", str(fifo), str(tmp_path)):
        assert_refused(cook2ltl("library", "import", special, "--library", str(library)), "Cannot read")
        assert_refused(cook2ltl("library", "edit", "2", "--body-file", special, "--no-validate",
                                "--library", str(library)))
    endless = subprocess.run(f"head -c 50000000 /dev/zero | {sys.executable} -m cook2ltl library edit 2 "
                             f"--body-file - --no-validate --library {library}", shell=True, capture_output=True,
                             text=True, timeout=120, env={**os.environ, "COLUMNS": "1000"})
    assert_refused(endless, "larger than the limit")
    assert library_state(library) == before


def test_an_export_file_over_the_limit_is_refused_whole(tmp_path, library, monkeypatch):
    from cook2ltl.library import limits

    path = export_of(tmp_path, library)
    monkeypatch.setattr(limits, "EXPORT_BYTES", path.stat().st_size - 1)
    store = Library(library)
    with pytest.raises(UserError, match="larger than the limit"):
        import_library(store, path, "eve")
    store.close()


# --- paths -------------------------------------------------------------------------------------------------------

def test_home_relative_paths_are_expanded(tmp_path, library):
    home = tmp_path / "home"
    home.mkdir()

    def run(*arguments):
        return cook2ltl("library", *arguments, HOME=str(home))

    assert run("export", "~/lab.json", "--library", str(library)).returncode == 0
    assert run("import", "~/lab.json", "--library", "~/lib.sqlite").returncode == 0
    assert (home / "lab.json").is_file() and len(Library(home / "lib.sqlite").entries()) == 2
    assert not (tmp_path / "~").exists()
    assert_refused(run("list", "--library", "~no_such_user_cook2ltl/lib.sqlite"), "home folder")


@pytest.mark.parametrize("path", ["a" * 5000, "b" * 300 + "/lib.sqlite", "x/" * 2100 + "lib.sqlite"])
def test_over_long_paths_are_clear_errors_in_every_command(tmp_path, library, path):
    long = str(tmp_path / path)
    for command in (["list", "--library", long], ["export", long, "--library", str(library)],
                    ["import", long, "--library", str(library)],
                    ["edit", "2", "--body-file", long, "--no-validate", "--library", str(library)]):
        assert_refused(cook2ltl("library", *command), "too long")
