"""Issue 16, import: an approval made while an import runs is never replaced (statuses are compared and set inside
one transaction), the exchange format's edge values are refused with a message naming entry and field, and any
library survives an export and two imports unchanged."""

import copy
import json
import os
import sqlite3
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cook2ltl.errors import UserError
from cook2ltl.library import Library, Status
from cook2ltl.library.exchange import export_library, import_library

MINE, THEIRS = "pick_up($what)\nput($what, pot)", "pick_up($what)\nstir($what)"


def pending_here_and_another_body_in_a_file(folder: Path) -> tuple[Path, Path]:
    """A library whose entry 1 is pending, and an export with another body for the same action."""
    library = Library(folder / "library.sqlite")
    library.add("recipe", "boil", ("what",), MINE, "m", "h", validation="passed")
    library.close()
    other = Library(folder / "other.sqlite")
    other.add("recipe", "boil", ("what",), THEIRS, "m", "h", validation="passed")
    export_library(other, folder / "other.json")
    other.close()
    return folder / "library.sqlite", folder / "other.json"


def test_an_approval_made_while_an_import_waits_for_the_lock_is_never_replaced(tmp_path, monkeypatch):
    """(The import read its entries before its transaction: the approval was recorded, yet the entry ended
    pending with the imported body.) The approver holds the write lock; the import starts and, as the old one
    did, may read; then the approval commits, and only then can the import write."""
    path, exported = pending_here_and_another_body_in_a_file(tmp_path)
    importer, approver = Library(path), Library(path)
    read = threading.Event()
    entries = Library.entries

    def entries_then_tell(self):
        found = entries(self)
        if self is importer:
            read.set()
        return found

    monkeypatch.setattr(Library, "entries", entries_then_tell)
    opened, go, reports = threading.Event(), threading.Event(), []

    def run_import():
        importer.get(1)  # its connection opened before the approver takes the lock, as a running import's is
        opened.set()
        go.wait(timeout=30)
        reports.append(import_library(importer, exported, "eve", replace_pending=True))

    thread = threading.Thread(target=run_import)
    thread.start()
    opened.wait(timeout=30)
    with approver.transaction():
        go.set()
        read.wait(timeout=3)  # the fixed import reads only once it holds the lock: after this approval
        approver.set_status(1, Status.APPROVED, by="ann")
    thread.join(timeout=60)
    entry = approver.get(1)
    assert (entry.status, entry.body, entry.reviewed_by) == (Status.APPROVED, MINE, "ann")
    assert reports[0].conflicts == ("recipe boil(what): entry 1 is approved here with another body; kept",)
    for store in (importer, approver):
        store.close()


def cook2ltl(*arguments: str) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "cook2ltl", "library", *arguments], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env={**os.environ, "COOK2LTL_USER": "ann"})


@pytest.mark.parametrize("attempt", range(3))
def test_an_import_racing_an_approve_never_loses_the_approval(tmp_path, attempt):
    path, exported = pending_here_and_another_body_in_a_file(tmp_path)
    runs = [cook2ltl("import", str(exported), "--replace-pending", "--library", str(path)),
            cook2ltl("approve", "1", "--library", str(path))]
    for run in runs:
        _, err = run.communicate(timeout=120)
        assert run.returncode == 0, err
    store = Library(path)
    entry, reviews = store.get(1), store.reviews(1)
    store.close()
    # Whichever came first, the entry ends approved, and the approval is of the body it has now.
    assert entry.status == Status.APPROVED and entry.reviewed_by == "ann"
    assert (reviews[-1].status, reviews[-1].version) == ("approved", entry.version)


def test_an_edit_of_an_entry_changed_meanwhile_saves_nothing(tmp_path):
    store = Library(tmp_path / "library.sqlite")
    seen = store.add("recipe", "boil", ("what",), MINE, "m", "h")
    store.set_status(seen.id, Status.APPROVED, by="ann")  # someone else, while the editor ran the kitchen check
    with pytest.raises(UserError, match="changed meanwhile: it is approved version 1 now, not pending version 1"):
        store.edit(seen.id, THEIRS, "bob", expected=seen)
    assert store.get(seen.id).body == MINE and store.get(seen.id).status == Status.APPROVED
    store.close()


@pytest.fixture(scope="module")
def good(tmp_path_factory) -> dict:
    folder = tmp_path_factory.mktemp("good")
    store = Library(folder / "source.sqlite")
    entry = store.add("recipe", "boil", ("what",), MINE, "m", "h", validation="passed", example={"$what": "egg"})
    store.set_status(entry.id, Status.APPROVED, by="ann")
    export_library(store, folder / "good.json")
    store.close()
    return json.loads((folder / "good.json").read_text())


def changed(document: dict, change) -> dict:
    document = copy.deepcopy(document)
    change(document["entries"][0])
    return document


EDGES = {
    "a huge version": (lambda e: e["history"][0].update(version=10**30),
                       '"history" item 1, "version": must be at most'),
    "a version past 64 bits": (lambda e: e["history"][0].update(version=2**63), "must be at most 1,000,000,000"),
    "a huge restores": (lambda e: e["history"][0].update(restores=2**64), '"restores": must be at most'),
    "a negative review version": (lambda e: e["reviews"][0].update(version=-1), '"version": must be at least 1'),
    "a signature with a comma": (lambda e: e.update(signature=["what,where"]), '"signature" item 1: must be a name'),
    "an empty slot": (lambda e: e.update(signature=["", "what"]), '"signature" item 1: must be a name'),
    "a slot with a digit": (lambda e: e.update(signature=["what2"]), '"signature" item 1: must be a name'),
    "a verb with a space": (lambda e: e.update(verb="pick up"), '"verb": must be a name such as boil'),
    "markup as a verb": (lambda e: e.update(verb="[/nope]"), '"verb": must be a name'),
    "a control character": (lambda e: e.update(model="qwen\x1b[31m"), '"model": has a control character'),
    "a verb of 10,000 characters": (lambda e: e.update(verb="a" * 10_000), '"verb": is longer than 200 characters'),
    "a boolean as a version": (lambda e: e["history"][0].update(version=True), "must be a whole number, not true"),
    "a float as a version": (lambda e: e["history"][0].update(version=1.0), "must be a whole number, not 1.0"),
    "a string as a version": (lambda e: e["history"][0].update(version="1"), 'must be a whole number, not "1"'),
    "a million problems": (lambda e: e.update(problems=["x"] * 1_000_001), '"problems": has more than 1,000 items'),
    "an example key without $": (lambda e: e.update(example={"what": "egg"}), '"example", "what": must be a name'),
    "a time of year 99999": (lambda e: e.update(created="99999-01-01"), '"created": must be an ISO 8601 time'),
}


@pytest.mark.parametrize("name", EDGES)
def test_edge_values_are_refused_naming_the_entry_and_the_field(tmp_path, good, name):
    change, message = EDGES[name]
    (tmp_path / "edge.json").write_text(json.dumps(changed(good, change)))
    store = Library(tmp_path / "library.sqlite")
    with pytest.raises(UserError, match="edge.json: entry 1[,:] ") as raised:
        import_library(store, tmp_path / "edge.json", "eve")
    assert message in raised.value.message and "\n" not in raised.value.message
    assert store.entries() == ()
    store.close()


def test_an_approved_entry_that_failed_its_kitchen_check_is_imported_approved_only_with_force(tmp_path, good):
    document = changed(good, lambda e: e.update(validation="failed", problems=["the egg is not in the pot"]))
    (tmp_path / "failed.json").write_text(json.dumps(document))
    store = Library(tmp_path / "library.sqlite")
    with pytest.raises(UserError, match="entry 1 .recipe boil.what.. is approved but failed the kitchen check: "
                                        "the egg is not in the pot") as raised:
        import_library(store, tmp_path / "failed.json", "eve")
    assert "--force" in raised.value.hint and store.entries() == ()
    import_library(store, tmp_path / "failed.json", "eve", force=True)
    assert store.get(1).status == Status.APPROVED and store.get(1).validation == "failed"
    store.close()


slots = st.lists(st.sampled_from(["what", "where", "how", "time", "temperature"]), max_size=3)
calls = st.lists(st.sampled_from(["pick_up($what)", "put($what, pot)", "stir($what)", "open(fridge)",
                                  "wait($what == boiled)", "# a comment"]), max_size=4).map("\n".join)
verbs = st.from_regex(r"[a-z][a-z0-9_]{0,8}", fullmatch=True)
entries = st.lists(st.tuples(st.sampled_from(["recipe", "ai2thor"]), verbs, slots, calls, st.sampled_from(list(Status)),
                             st.sampled_from(["passed", "unchecked"]), st.lists(calls, max_size=2)), max_size=6)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(entries)
def test_any_library_survives_an_export_and_two_imports(drawn):
    """(A signature slot with a comma was split when stored, so importing the same file again aborted.)"""
    with tempfile.TemporaryDirectory() as folder:
        source = Library(Path(folder) / "source.sqlite")
        for primitives, verb, signature, body, status, validation, edits in drawn:
            entry = source.add(primitives, verb, tuple(signature), body, "m", "h", validation=validation)
            for edit in edits:
                source.edit(entry.id, edit, "bob")
            if status != Status.PENDING and (status == Status.REJECTED or source.get(entry.id).has_plan):
                source.set_status(entry.id, status, by="ann")
        export_library(source, Path(folder) / "lab.json")
        target = Library(Path(folder) / "target.sqlite")
        import_library(target, Path(folder) / "lab.json", "eve")
        before = dump(target.path)
        again = import_library(target, Path(folder) / "lab.json", "eve", replace_pending=True)
        assert again.added == () and again.replaced == () and dump(target.path) == before
        def approved(store):
            return [(e.verb, e.signature, e.body) for e in store.entries() if e.status == Status.APPROVED]

        assert approved(target) == approved(source)
        for store in (source, target):
            store.close()


def dump(path) -> list[str]:
    with sqlite3.connect(path) as conn:
        return list(conn.iterdump())
