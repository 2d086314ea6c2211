"""Two processes on one library file at once: writers wait for each other (WAL, busy timeout), readers never
see half a write, and nothing is lost."""

import sqlite3
import subprocess
import sys
import time

from cook2ltl.library import Library, Status

WRITER = """
import sys
from pathlib import Path
from cook2ltl.library import Library, Status
store = Library(Path(sys.argv[1]))
name, count = sys.argv[2], int(sys.argv[3])
for number in range(count):
    entry = store.add("recipe", f"{name}_{number}", ("what",), "pick_up($what)\\nput($what, pot)", "m", "h")
    store.set_status(entry.id, Status.APPROVED, by=name)
    store.edit(entry.id, "pick_up($what)\\nstir($what)", by=name, note="second body")
store.close()
print("done")
"""

WHOLE_ENTRIES = ("SELECT a.id, a.body, (SELECT v.body FROM versions v WHERE v.entry_id = a.id "
                 "ORDER BY v.version DESC LIMIT 1) FROM actions a")


def test_two_writers_and_a_reader_at_once(tmp_path):
    path = tmp_path / "library.sqlite"
    Library(path).close()
    count = 150
    writers = [subprocess.Popen([sys.executable, "-c", WRITER, str(path), name, str(count)],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for name in ("ann", "bob")]
    reader = Library(path)
    snapshot = sqlite3.connect(path, timeout=30)
    seen, listed = set(), None
    try:
        while any(w.poll() is None for w in writers):
            # One statement reads one snapshot: every entry with its current body as its newest version.
            rows = snapshot.execute(WHOLE_ENTRIES).fetchall()
            assert all(body == newest for _, body, newest in rows), "an entry without its version"
            seen.add(len(reader.entries()))
            if max(seen) and listed is None:  # and a third process, the CLI, reads while they write
                listed = subprocess.run([sys.executable, "-m", "cook2ltl", "library", "list", "--library", str(path)],
                                        capture_output=True, text=True, timeout=60)
                assert listed.returncode == 0 and "pick_up" not in listed.stderr, listed.stderr
            time.sleep(0.02)
        for writer in writers:
            out, err = writer.communicate(timeout=120)
            assert writer.returncode == 0 and out.strip() == "done", err
        final = reader.entries()
    finally:
        reader.close()
        snapshot.close()
    assert len(final) == 2 * count and listed is not None
    assert any(0 < number < 2 * count for number in seen), "the reader should have read while they wrote"
    assert all(e.status == Status.PENDING and e.version == 2 and e.body.endswith("stir($what)") for e in final)
    assert {e.verb.split("_")[0] for e in final} == {"ann", "bob"}
    with sqlite3.connect(path) as conn:
        assert conn.execute("PRAGMA journal_mode").fetchone() == ("wal",)
        assert conn.execute("PRAGMA integrity_check").fetchall() == [("ok",)]
        conn.execute("INSERT INTO actions_fts (actions_fts) VALUES ('integrity-check')")  # raises if out of step


def test_a_cli_write_waits_for_a_long_transaction_of_another_process(tmp_path):
    path = tmp_path / "library.sqlite"
    store = Library(path)
    entry = store.add("recipe", "boil", ("what",), "pick_up($what)", "m", "h")
    holder = subprocess.Popen(
        [sys.executable, "-c",
         "import sqlite3, sys, time\nconn = sqlite3.connect(sys.argv[1], isolation_level=None)\n"
         "conn.execute('BEGIN IMMEDIATE'); print('locked', flush=True); time.sleep(2); conn.execute('COMMIT')",
         str(path)], stdout=subprocess.PIPE, text=True)
    assert holder.stdout.readline().strip() == "locked"
    started = time.monotonic()
    approved = subprocess.run([sys.executable, "-m", "cook2ltl", "library", "approve", str(entry.id),
                               "--library", str(path), "--by", "carol"], capture_output=True, text=True, timeout=60)
    holder.wait(30)
    assert approved.returncode == 0, approved.stderr
    assert time.monotonic() - started >= 1.0  # it waited for the lock instead of failing
    assert store.get(entry.id).status == Status.APPROVED and store.get(entry.id).reviewed_by == "carol"
    store.close()
