"""The action library 𝔸 in SQLite: round trips, review status, schema version, and a user's file kept safe."""

import sqlite3
import threading

import pytest

from cook2ltl import paths
from cook2ltl.errors import UserError
from cook2ltl.library import schema
from cook2ltl.library.store import SCHEMA_VERSION, Library, Status


@pytest.fixture
def library(tmp_path):
    opened = Library(tmp_path / "library.sqlite")
    yield opened
    opened.close()


def add(library, verb="boil", signature=("what",), body="put($what, pot)", primitives="recipe", **kwargs):
    return library.add(primitives, verb, signature, body, "qwen", "abc123", **kwargs)


def test_round_trip_with_provenance(library, tmp_path):
    entry = add(library, body="pick_up($what)\nput($what, microwave)")
    assert library.lookup("recipe", "boil", ("what",)) == entry
    assert (entry.status, entry.model, entry.prompt_hash) == (Status.PENDING, "qwen", "abc123")
    assert entry.created.endswith("+00:00")
    library.close()
    reopened = Library(tmp_path / "library.sqlite")
    assert reopened.lookup("recipe", "boil", ("what",)).body == "pick_up($what)\nput($what, microwave)"
    reopened.close()


def test_lookup_needs_the_same_set_verb_and_signature(library):
    add(library)
    assert library.lookup("recipe", "boil", ("what", "time")) is None
    assert library.lookup("ai2thor", "boil", ("what",)) is None
    assert library.lookup("recipe", "fry", ("what",)) is None
    add(library, signature=())
    assert library.lookup("recipe", "boil", ()).signature == ()


def test_one_live_entry_per_action_and_rejected_ones_are_skipped(library):
    first = add(library)
    assert add(library, body="other($what)") == first  # stored by someone else first: theirs is kept
    library.set_status(first.id, Status.REJECTED)
    assert library.lookup("recipe", "boil", ("what",)) is None
    second = add(library, body="stir($what)")
    library.set_status(second.id, Status.APPROVED)
    assert library.lookup("recipe", "boil", ("what",)).status == Status.APPROVED
    assert [e.id for e in library.live("recipe")] == [second.id]
    assert len(library.entries()) == 2


def test_replacing_a_stale_entry_rejects_it_in_the_same_transaction(library):
    stale = add(library)
    fresh = add(library, body="stir($what)", replacing=stale.id)
    assert {e.id: e.status for e in library.entries()} == {stale.id: Status.REJECTED, fresh.id: Status.PENDING}


def test_unknown_entry_is_a_user_error(library):
    with pytest.raises(UserError, match="No entry 99"):
        library.set_status(99, Status.APPROVED)


def test_each_thread_has_its_own_connection(library):
    entry = add(library)
    found = []
    worker = threading.Thread(target=lambda: found.append(library.lookup("recipe", "boil", ("what",))))
    worker.start()
    worker.join()
    assert found == [entry]


def test_schema_version_and_wal(library, tmp_path):
    conn = sqlite3.connect(tmp_path / "library.sqlite")
    assert conn.execute("PRAGMA user_version").fetchone()[0] == SCHEMA_VERSION >= 1
    assert conn.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
    conn.close()


def test_a_newer_library_is_refused(tmp_path):
    path = tmp_path / "library.sqlite"
    Library(path).close()
    conn = sqlite3.connect(path)
    conn.execute(f"PRAGMA user_version = {SCHEMA_VERSION + 1}")
    conn.commit()
    conn.close()
    with pytest.raises(UserError, match="schema version") as raised:
        Library(path)
    assert "upgrade cook2ltl" in raised.value.hint


@pytest.mark.parametrize("make", [
    lambda path: path.write_bytes(b"recipes, not a database\n" * 100),
    lambda path: sqlite3.connect(path).execute("CREATE TABLE mine (x)").connection.commit(),
    lambda path: path.mkdir(),
])
def test_a_file_that_is_not_a_library_is_left_alone(tmp_path, make):
    path = tmp_path / "library.sqlite"
    make(path)
    before = path.read_bytes() if path.is_file() else None
    with pytest.raises(UserError) as raised:
        Library(path)
    assert raised.value.hint
    assert (path.read_bytes() if path.is_file() else None) == before


def test_a_failing_migration_leaves_the_file_as_it_was(tmp_path, monkeypatch):
    path = tmp_path / "library.sqlite"
    Library(path).close()

    def broken(db):
        db.conn.execute("CREATE TABLE half_done (x)")
        raise RuntimeError("disk on fire")

    monkeypatch.setattr(schema, "MIGRATIONS", (*schema.MIGRATIONS, broken))
    with pytest.raises(RuntimeError):
        Library(path)
    conn = sqlite3.connect(path)
    assert conn.execute("PRAGMA user_version").fetchone()[0] == SCHEMA_VERSION
    assert not conn.execute("SELECT name FROM sqlite_master WHERE name = 'half_done'").fetchall()
    conn.close()


def test_the_library_path_follows_the_environment(monkeypatch, tmp_path):
    monkeypatch.setenv("COOK2LTL_LIBRARY", str(tmp_path / "lab.sqlite"))
    assert paths.library_file() == tmp_path / "lab.sqlite"
    monkeypatch.delenv("COOK2LTL_LIBRARY")
    monkeypatch.setenv("COOK2LTL_DATA", str(tmp_path / "data"))
    assert paths.library_file() == tmp_path / "data" / "library.sqlite"
