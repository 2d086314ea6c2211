"""`cook2ltl library` on a real SQLite library file, edits checked in the real embedded kitchen."""

import json
import os
import sqlite3
import subprocess
import sys

import pytest

from cook2ltl.library import Library, Status

BOIL = "pick_up($what)\nput($what, pot)"  # the egg is in the closed fridge: THOR refuses the pick up
# The pot on the burner first: the kitchen check wants boil's goal state, a hot egg, at the end.
GOOD = "pick_up(pot)\nput(pot, stovetop)\nopen(fridge)\npick_up($what)\nput($what, pot)\nturn_on(stovetop)\nwait($what == boiled)"


def cook2ltl(*arguments: str, stdin: str | None = None, user: str = "lab-tester") -> subprocess.CompletedProcess:
    env = {**os.environ, "COOK2LTL_USER": user, "HF_HUB_OFFLINE": "1"}
    return subprocess.run([sys.executable, "-m", "cook2ltl", *arguments], capture_output=True, text=True,
                          timeout=180, input=stdin, env=env)


@pytest.fixture
def seeded(tmp_path):
    path = tmp_path / "library.sqlite"
    store = Library(path)
    store.add("recipe", "boil", ("what",), BOIL, "qwen", "abc123def4567890", example={"$what": "egg"})
    store.add("recipe", "fry", ("what",), "put($what, pan)", "qwen", "x", validation="failed",
              problems=["line 1 put(egg, pan): the agent holds nothing"], example={"$what": "egg"})
    store.close()
    return path


def entry(path, entry_id=1):
    store = Library(path)
    try:
        return store.get(entry_id), store.history(entry_id)
    finally:
        store.close()


def dump(path) -> list[str]:
    conn = sqlite3.connect(path)
    lines = list(conn.iterdump())
    conn.close()
    return lines


def test_list_show_approve_and_reject_record_who(seeded):
    listed = cook2ltl("library", "list", "--library", str(seeded))
    assert listed.returncode == 0 and "boil(what)" in listed.stdout and "pending" in listed.stdout
    shown = cook2ltl("library", "show", "1", "--library", str(seeded))
    assert all(text in shown.stdout for text in ("put($what, pot)", "qwen", "abc123def456", "not reviewed yet",
                                                  "version 1", "unchecked", "$what = egg"))

    approved = cook2ltl("library", "approve", "1", "--library", str(seeded), "--by", "ann")
    assert approved.returncode == 0 and "approved by ann" in approved.stdout
    assert (entry(seeded)[0].status, entry(seeded)[0].reviewed_by) == (Status.APPROVED, "ann")
    assert "approved by ann at 20" in cook2ltl("library", "show", "1", "--library", str(seeded)).stdout
    assert cook2ltl("library", "reject", "1", "--library", str(seeded)).returncode == 0
    assert (entry(seeded)[0].status, entry(seeded)[0].reviewed_by) == (Status.REJECTED, "lab-tester")
    assert "boil" not in cook2ltl("library", "list", "--status", "approved", "--library", str(seeded)).stdout


def test_list_filters_by_status_and_search(seeded):
    found = cook2ltl("library", "list", "--search", "pan", "--library", str(seeded))
    assert "fry(what)" in found.stdout and "boil(what)" not in found.stdout
    assert "no entries" in cook2ltl("library", "list", "--search", "saucepan", "--library", str(seeded)).stdout
    bad = cook2ltl("library", "list", "--search", "put($what", "--library", str(seeded))
    assert bad.returncode == 2 and "Cannot search" in bad.stderr and "Traceback" not in bad.stderr
    wrong = cook2ltl("library", "list", "--status", "maybe", "--library", str(seeded))
    assert wrong.returncode == 2 and "not one of pending, approved, rejected" in wrong.stderr


def test_a_failed_entry_shows_its_problems_and_is_approved_only_with_force(seeded):
    shown = cook2ltl("library", "show", "2", "--library", str(seeded))
    assert "failed" in shown.stdout and "line 1 put(egg, pan): the agent holds nothing" in shown.stdout
    refused = cook2ltl("library", "approve", "2", "--library", str(seeded))
    assert refused.returncode == 2 and "--force" in refused.stderr
    assert entry(seeded, 2)[0].status == Status.PENDING
    assert cook2ltl("library", "approve", "2", "--force", "--library", str(seeded)).returncode == 0
    assert entry(seeded, 2)[0].status == Status.APPROVED


def test_an_edit_with_a_bad_body_prints_each_problem_and_saves_nothing(seeded, tmp_path):
    body = tmp_path / "body.txt"
    body.write_text("put($what)\nfly($what)\n\nput $what in pot\n")
    before = dump(seeded)
    edited = cook2ltl("library", "edit", "1", "--body-file", str(body), "--library", str(seeded))
    assert edited.returncode == 2
    assert edited.stderr.count("✗") == 3
    assert "line 1: put takes 2 arguments, not 1" in edited.stderr
    assert "line 2: fly with 1 argument(s)" in edited.stderr and "line 4: “put $what in pot”" in edited.stderr
    assert "nothing saved" in edited.stderr and dump(seeded) == before


def test_an_edit_from_stdin_is_run_in_the_kitchen_and_stored_as_a_new_version(seeded):
    edited = cook2ltl("library", "edit", "1", "--body-file", "-", "--note", "open the fridge first",
                      "--library", str(seeded), stdin=GOOD + "\n")
    assert edited.returncode == 0, edited.stderr
    assert "version 2, kitchen check passed" in edited.stdout
    current, history = entry(seeded)
    assert (current.body, current.validation, current.status, current.version) == (GOOD, "passed", Status.PENDING, 2)
    assert [(v.author, v.note) for v in history] == [("qwen", "learnt"), ("lab-tester", "open the fridge first")]


def test_an_edit_that_fails_in_the_kitchen_is_saved_only_when_asked(seeded):
    before = dump(seeded)
    failing = cook2ltl("library", "edit", "1", "--body-file", "-", "--library", str(seeded), stdin="put($what, pot)")
    assert failing.returncode == 1 and "fails the kitchen check" in failing.stderr
    assert "line 1 put(egg, pot): the agent holds nothing" in failing.stdout
    assert dump(seeded) == before
    kept = cook2ltl("library", "edit", "1", "--body-file", "-", "--keep-failing", "--library", str(seeded),
                    stdin="put($what, pot)")
    assert kept.returncode == 0 and "kitchen check failed" in kept.stdout
    current, _ = entry(seeded)
    assert (current.validation, current.problems) == (
        "failed", ("line 1 put(egg, pot): the agent holds nothing; the plan must pick up egg first",
                   "boil(egg): goal state not reached: egg is not hot at the end"))


def test_an_edit_without_the_kitchen_or_without_example_values_is_unchecked(seeded):
    skipped = cook2ltl("library", "edit", "1", "--body-file", "-", "--no-validate", "--library", str(seeded),
                       stdin="put($what, pot)")
    assert skipped.returncode == 0 and entry(seeded)[0].validation == "unchecked"
    store = Library(seeded)
    old = store.add("recipe", "stew", ("what",), "stir($what)", "qwen", "y")  # learnt before examples were kept
    store.close()
    edited = cook2ltl("library", "edit", str(old.id), "--body-file", "-", "--library", str(seeded),
                      stdin="stir($what)\ntaste($what)")
    assert edited.returncode == 0 and "no example values" in edited.stdout
    assert entry(seeded, old.id)[0].validation == "unchecked"


def test_history_and_undo(seeded):
    cook2ltl("library", "approve", "1", "--by", "ann", "--library", str(seeded))
    cook2ltl("library", "edit", "1", "--body-file", "-", "--no-validate", "--by", "bob", "--library", str(seeded),
             stdin="pick_up($what)\nput($what, saucepan)")
    history = cook2ltl("library", "history", "1", "--library", str(seeded))
    assert history.returncode == 0 and "saucepan" in history.stdout and "bob" in history.stdout
    assert "version 1 approved by ann at 20" in history.stdout
    undone = cook2ltl("library", "undo", "1", "--library", str(seeded))
    assert undone.returncode == 0 and "the body of version 1 is back as version 3" in undone.stdout
    current, versions = entry(seeded)
    assert (current.body, versions[-1].author, versions[-1].restores) == (BOIL, "lab-tester", 1)
    nothing = cook2ltl("library", "undo", "2", "--library", str(seeded))
    assert nothing.returncode == 2 and "no earlier version" in nothing.stderr


def test_export_and_import_round_trip_and_conflicts(seeded, tmp_path):
    exported = tmp_path / "lab.json"
    assert cook2ltl("library", "export", str(exported), "--library", str(seeded)).returncode == 0
    assert [e["verb"] for e in json.loads(exported.read_text())["entries"]] == ["boil", "fry"]
    other = tmp_path / "other.sqlite"
    store = Library(other)
    mine = store.add("recipe", "fry", ("what",), "pick_up($what)\nput($what, skillet)", "smollm", "z")
    store.set_status(mine.id, Status.APPROVED, by="dan")
    store.close()
    imported = cook2ltl("library", "import", str(exported), "--by", "eve", "--library", str(other))
    assert imported.returncode == 0
    assert "added recipe boil(what)" in imported.stdout
    assert "conflict recipe fry(what): entry 1 is approved here with another body; kept" in imported.stdout
    assert "1 added, 0 unchanged, 0 replaced, 1 conflict(s)" in imported.stdout
    boil, history = entry(other, 2)
    assert (boil.body, history[-1].author, history[-1].note) == (BOIL, "eve", "imported from lab.json")
    assert entry(other, 1)[0].body.endswith("skillet)")
    again = cook2ltl("library", "import", str(exported), "--library", str(other))
    assert "0 added, 1 unchanged" in again.stdout


@pytest.mark.parametrize("content", [b"{not json", b'{"schema_version": 9, "entries": []}', bytes(range(256)),
                                     b'{"schema_version": 2, "entries": [{"verb": "boil"}]}'])
def test_a_malformed_import_is_a_clear_error_and_changes_nothing(seeded, tmp_path, content):
    bad = tmp_path / "bad.json"
    bad.write_bytes(content)
    before = dump(seeded)
    result = cook2ltl("library", "import", str(bad), "--library", str(seeded))
    assert result.returncode == 2 and "bad.json" in result.stderr and "hint:" in result.stderr
    assert "Traceback" not in result.stderr and dump(seeded) == before


def test_an_unknown_entry_or_a_file_that_is_not_a_library_is_a_clear_error(seeded, tmp_path):
    for command in (("approve", "99"), ("show", "99"), ("history", "99"), ("undo", "99")):
        missing = cook2ltl("library", *command, "--library", str(seeded))
        assert missing.returncode == 2 and "No entry 99" in missing.stderr and "Traceback" not in missing.stderr
    not_a_library = tmp_path / "notes.sqlite"
    not_a_library.write_text("just some notes")
    broken = cook2ltl("library", "list", "--library", str(not_a_library))
    assert broken.returncode == 2 and "Traceback" not in broken.stderr
    assert not_a_library.read_text() == "just some notes"
