"""A library written by the first schema (version 1) is brought to the current one in place, entries kept."""

import sqlite3

from sqlite_utils import Database

from cook2ltl.library import SCHEMA_VERSION, Library, Status
from cook2ltl.library.schema import MIGRATIONS

V1_ROWS = [  # as the version-1 store wrote them
    {"primitives": "recipe", "verb": "boil", "signature": "what", "body": "pick_up($what)\nput($what, pot)",
     "status": "approved", "model": "qwen", "prompt_hash": "aaa", "created": "2026-01-02T03:04:05+00:00"},
    {"primitives": "recipe", "verb": "fry", "signature": "what,where", "body": "put($what, $where)",
     "status": "rejected", "model": "qwen", "prompt_hash": "bbb", "created": "2026-01-03T03:04:05+00:00"},
    {"primitives": "ai2thor", "verb": "rinse", "signature": "", "body": "toggle_on(faucet)",
     "status": "pending", "model": "smollm", "prompt_hash": "ccc", "created": "2026-01-04T03:04:05+00:00"},
]


def version_1_library(path):
    conn = sqlite3.connect(path)
    db = Database(conn)
    MIGRATIONS[0](db)  # the version-1 schema, exactly as released
    conn.execute("PRAGMA user_version = 1")
    db["actions"].insert_all(V1_ROWS)
    conn.commit()
    conn.close()
    return path


def test_a_version_1_library_migrates_in_place_with_every_entry_kept(tmp_path):
    library = Library(version_1_library(tmp_path / "old.sqlite"))
    entries = library.entries()
    assert [(e.verb, e.signature, e.body, e.status, e.model, e.prompt_hash, e.created) for e in entries] == [
        (r["verb"], tuple(p for p in r["signature"].split(",") if p), r["body"], Status(r["status"]), r["model"],
         r["prompt_hash"], r["created"]) for r in V1_ROWS]
    assert all((e.validation, e.problems, e.version, e.example, e.reviewed_by) == ("unchecked", (), 1, (), None)
               for e in entries)
    history = library.history(entries[0].id)
    assert [(v.version, v.body, v.author, v.at, v.note) for v in history] == [
        (1, V1_ROWS[0]["body"], "qwen", V1_ROWS[0]["created"], "learnt")]
    library.close()
    conn = sqlite3.connect(tmp_path / "old.sqlite")
    assert conn.execute("PRAGMA user_version").fetchone()[0] == SCHEMA_VERSION == 4
    conn.close()


def test_a_migrated_library_is_searchable_and_keeps_its_rules(tmp_path):
    library = Library(version_1_library(tmp_path / "old.sqlite"))
    assert [e.verb for e in library.search("pot")] == ["boil"]
    assert [e.verb for e in library.search("faucet")] == ["rinse"]
    assert library.lookup("recipe", "fry", ("what", "where")) is None  # rejected stays unused
    assert library.lookup("recipe", "boil", ("what",), approved_only=True).body == V1_ROWS[0]["body"]
    edited = library.edit(library.entries()[2].id, "toggle_on(faucet)\ntoggle_off(faucet)", "ann")
    assert edited.version == 2 and [e.verb for e in library.search("toggle_off")] == ["rinse"]
    library.close()


def test_migrating_twice_is_a_no_op(tmp_path):
    path = version_1_library(tmp_path / "old.sqlite")
    Library(path).close()
    library = Library(path)
    assert len(library.entries()) == 3 and len(library.history(1)) == 1
    library.close()


def test_a_version_2_library_gets_a_review_log_from_its_last_reviews(tmp_path):
    path = tmp_path / "v2.sqlite"
    conn = sqlite3.connect(path)
    db = Database(conn)
    conn.execute("BEGIN")
    for migration in MIGRATIONS[:2]:
        migration(db)
    conn.execute("PRAGMA user_version = 2")
    db["actions"].insert_all(V1_ROWS)
    conn.execute("UPDATE actions SET reviewed_by = 'ann', reviewed_at = '2026-02-01T00:00:00+00:00' "
                 "WHERE status = 'approved'")
    conn.execute("COMMIT")
    conn.close()
    library = Library(path)
    assert [(r.version, r.status, r.reviewer, r.at) for r in library.reviews(1)] == [
        (1, "approved", "ann", "2026-02-01T00:00:00+00:00")]
    assert library.reviews(2) == () and library.reviews(3) == ()
    assert [e.verb for e in library.search("pot")] == ["boil"]  # rows added after migration 2 are indexed
    library.close()
