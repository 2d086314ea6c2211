"""`cook2ltl library` on a real SQLite library file."""

import subprocess
import sys

from cook2ltl.library import Library, Status


def cook2ltl(*arguments: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "cook2ltl", *arguments], capture_output=True, text=True, timeout=120)


def seeded(tmp_path):
    path = tmp_path / "library.sqlite"
    store = Library(path)
    entry = store.add("recipe", "boil", ("what",), "pick_up($what)\nput($what, pot)", "qwen", "abc123")
    store.close()
    return path, entry.id


def test_list_show_approve_and_reject(tmp_path):
    path, entry_id = seeded(tmp_path)
    listed = cook2ltl("library", "list", "--library", str(path))
    assert listed.returncode == 0 and "boil(what)" in listed.stdout and "pending" in listed.stdout
    shown = cook2ltl("library", "show", str(entry_id), "--library", str(path))
    assert "put($what, pot)" in shown.stdout and "qwen" in shown.stdout

    assert cook2ltl("library", "approve", str(entry_id), "--library", str(path)).returncode == 0
    assert Library(path).entries()[0].status == Status.APPROVED
    assert cook2ltl("library", "reject", str(entry_id), "--library", str(path)).returncode == 0
    assert Library(path).entries()[0].status == Status.REJECTED
    assert "boil" not in cook2ltl("library", "list", "--status", "approved", "--library", str(path)).stdout


def test_an_unknown_entry_or_a_file_that_is_not_a_library_is_a_clear_error(tmp_path):
    path, _ = seeded(tmp_path)
    missing = cook2ltl("library", "approve", "99", "--library", str(path))
    assert missing.returncode == 2 and "No entry 99" in missing.stderr and "Traceback" not in missing.stderr
    not_a_library = tmp_path / "notes.sqlite"
    not_a_library.write_text("just some notes")
    broken = cook2ltl("library", "list", "--library", str(not_a_library))
    assert broken.returncode == 2 and "Traceback" not in broken.stderr
    assert not_a_library.read_text() == "just some notes"
