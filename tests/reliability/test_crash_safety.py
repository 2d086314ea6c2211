"""`kill -9` in the middle of a real `cook2ltl translate` (tiny model, kitchen check on) leaves a library that
passes SQLite's integrity check with every approved entry as it was, and no kitchen process behind."""

import signal
import sqlite3
import subprocess
import sys
import time
from collections.abc import Callable

from cook2ltl.library import Library, Status
from tests.models_required import require_models
from tests.reliability.processes import children, wait_until_gone

RECIPE = "\n".join([
    "Garnish the salad.", "Microwave the potato.", "Chop the tomato.", "Toast the bread.", "Refrigerate the apple.",
    "Whisk the egg.", "Heat the pan.", "Wash the lettuce.", "Season the soup.", "Mash the potato.",
    "Peel the apple.", "Grill the bread.",
])
APPROVED = {
    ("garnish", ("what",)): "pick_up($what)\nput($what, plate)",
    ("season", ("what",)): "pick_up(salt_shaker)\nuse(salt_shaker)\nput(salt_shaker, countertop)",
}


def seeded_library(path):
    store = Library(path)
    for (verb, signature), body in APPROVED.items():
        entry = store.add("ai2thor", verb, signature, body, "hand-written", "none")
        store.set_status(entry.id, Status.APPROVED, by="tester")
    store.close()


def entries(path) -> int:
    with sqlite3.connect(path, timeout=30) as conn:
        return conn.execute("SELECT count(*) FROM actions").fetchone()[0]


def test_kill_9_during_a_translation_loses_nothing_approved_and_leaves_no_process(tmp_path):
    require_models("smollm2-135m", "gliner-cook2ltl", "spacy-sm")
    library = tmp_path / "library.sqlite"
    seeded_library(library)
    (tmp_path / "recipe.txt").write_text(RECIPE)
    command = ["translate", str(tmp_path / "recipe.txt"), "--primitives", "ai2thor", "--model", "smollm2-135m",
               "--library", str(library), "--validate", "--repairs", "0", "--max-lines", "4"]
    # Mid-way: two new reductions stored, more to come.
    started = kill_9_when(command, lambda: entries(library) >= len(APPROVED) + 2, 240, "new library entry", tmp_path)
    assert started, "the kitchen check should have started the embedded kitchen"
    assert wait_until_gone(started, timeout=10) == set(), "a kitchen process outlived the killed translation"

    with sqlite3.connect(library) as conn:
        assert conn.execute("PRAGMA integrity_check").fetchall() == [("ok",)]
        assert conn.execute("PRAGMA foreign_key_check").fetchall() == []
        conn.execute("INSERT INTO actions_fts (actions_fts) VALUES ('integrity-check')")  # the search index too
    store = Library(library)
    try:
        kept = {(e.verb, e.signature): e for e in store.entries() if e.status == Status.APPROVED}
        assert {key: e.body for key, e in kept.items()} == APPROVED
        assert all(e.reviewed_by == "tester" for e in kept.values())
        assert len(store.entries()) >= len(APPROVED) + 2
        for entry in store.entries():  # every stored entry is whole: its current body is its last version
            assert store.history(entry.id)[-1].body == entry.body
    finally:
        store.close()


def test_kill_9_during_a_large_import_leaves_all_or_nothing(tmp_path):
    from cook2ltl.library.exchange import export_library

    source = Library(tmp_path / "source.sqlite")
    with source.transaction():
        for number in range(3000):
            source.add("recipe", f"verb_{number}", ("what",), "pick_up($what)\nstir($what)", "m", "h")
    export_library(source, tmp_path / "export.json")
    source.close()
    library = tmp_path / "library.sqlite"
    seeded_library(library)
    command = ["library", "import", str(tmp_path / "export.json"), "--library", str(library)]
    kill_9_when(command, lambda: writing(library), 120, "write transaction", tmp_path)  # inside its one transaction
    with sqlite3.connect(library) as conn:
        assert conn.execute("PRAGMA integrity_check").fetchall() == [("ok",)]
        count = conn.execute("SELECT count(*) FROM actions").fetchone()[0]
    assert count in (len(APPROVED), len(APPROVED) + 3000)  # all of the import or none of it
    store = Library(library)
    kept = {(e.verb, e.signature): e.body for e in store.entries() if e.status == Status.APPROVED}
    assert kept == APPROVED
    store.close()


def kill_9_when(command: list[str], ready: Callable[[], bool], timeout: float, awaited: str, cwd) -> set[int]:
    """Run `cook2ltl <command>` and kill -9 it as soon as `ready()` holds; the processes it had started then."""
    run = subprocess.Popen([sys.executable, "-m", "cook2ltl", *command], stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, cwd=cwd)
    try:
        deadline = time.monotonic() + timeout
        while not ready():
            assert run.poll() is None, f"{command[0]} ended before it could be killed: {run.stderr.read()[-2000:]}"
            assert time.monotonic() < deadline, f"no {awaited} within {timeout} s"
            time.sleep(0.05)
        started = children(run.pid)
        run.send_signal(signal.SIGKILL)
        run.wait(10)
        return started
    finally:
        if run.poll() is None:
            run.kill()
            run.wait()
        run.stderr.close()


def writing(path) -> bool:
    """Whether another process holds the library's write lock."""
    conn = sqlite3.connect(path, timeout=0, isolation_level=None)
    try:
        conn.execute("BEGIN IMMEDIATE")
        conn.execute("ROLLBACK")
        return False
    except sqlite3.OperationalError:
        return True
    finally:
        conn.close()
