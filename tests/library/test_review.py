"""Review of the action library: who approved what and when, approvals win, edits keep every version."""

import sqlite3
import threading
from datetime import datetime, timezone

import pytest

from cook2ltl.errors import UserError
from cook2ltl.library import Library, Status, reviewer


@pytest.fixture
def library(tmp_path):
    opened = Library(tmp_path / "library.sqlite")
    yield opened
    opened.close()


def add(library, verb="boil", body="pick_up($what)\nput($what, pot)", **kwargs):
    return library.add("recipe", verb, ("what",), body, "qwen", "abc123", **kwargs)


def recent(stamp: str) -> bool:
    return abs((datetime.now(timezone.utc) - datetime.fromisoformat(stamp)).total_seconds()) < 60


def test_a_new_entry_is_pending_unreviewed_version_1_with_its_check_and_example(library):
    entry = add(library, validation="failed", problems=["line 2 put(egg, pot): not holding egg"],
                example={"$what": "egg"})
    assert (entry.status, entry.reviewed_by, entry.reviewed_at, entry.version) == (Status.PENDING, None, None, 1)
    assert library.get(entry.id) == entry
    assert entry.problems == ("line 2 put(egg, pot): not holding egg",) and dict(entry.example) == {"$what": "egg"}
    [first] = library.history(entry.id)
    assert (first.version, first.body, first.author, first.validation, first.at) == (
        1, entry.body, "qwen", "failed", entry.created)


def test_an_unknown_validation_is_refused(library):
    with pytest.raises(ValueError, match="validation"):
        add(library, validation="fine")
    assert library.entries() == ()


@pytest.mark.parametrize("status", [Status.APPROVED, Status.REJECTED, Status.PENDING])
def test_each_status_change_records_who_and_when(library, status):
    entry = add(library)
    changed = library.set_status(entry.id, status, by="ann")
    assert (changed.status, changed.reviewed_by) == (status, "ann") and recent(changed.reviewed_at)
    assert library.get(entry.id) == changed


def test_the_reviewer_defaults_to_cook2ltl_user(library, monkeypatch):
    monkeypatch.setenv("COOK2LTL_USER", "lab-robot-7")
    assert reviewer() == "lab-robot-7"
    assert library.set_status(add(library).id, Status.APPROVED).reviewed_by == "lab-robot-7"


def test_a_failed_body_is_approved_only_with_force(library):
    entry = add(library, validation="failed", problems=["line 1 pick_up(egg): egg is not in the scene"])
    with pytest.raises(UserError, match="egg is not in the scene") as raised:
        library.set_status(entry.id, Status.APPROVED, by="ann")
    assert "--force" in raised.value.hint and library.get(entry.id).status == Status.PENDING
    assert library.set_status(entry.id, Status.APPROVED, by="ann", force=True).status == Status.APPROVED


def test_a_new_reduction_never_replaces_an_approved_entry(library):
    approved = library.set_status(add(library).id, Status.APPROVED, by="ann")
    kept = add(library, body="stir($what)", replacing=approved.id)
    assert kept == approved
    assert [(e.id, e.status, e.body) for e in library.entries()] == [(approved.id, Status.APPROVED, approved.body)]


def test_a_new_reduction_replaces_a_pending_entry_and_says_who_rejected_it(library):
    stale = add(library)
    fresh = add(library, body="stir($what)", replacing=stale.id)
    rejected = library.get(stale.id)
    assert (rejected.status, rejected.reviewed_by) == (Status.REJECTED, "cook2ltl")
    assert library.lookup("recipe", "boil", ("what",)) == fresh


def test_rejected_entries_are_never_reused(library):
    entry = add(library)
    library.set_status(entry.id, Status.REJECTED, by="ann")
    assert library.lookup("recipe", "boil", ("what",)) is None
    assert library.lookup("recipe", "boil", ("what",), approved_only=True) is None
    assert library.live("recipe") == () and library.live("recipe", approved_only=True) == ()


def test_lab_mode_reuses_approved_entries_only(library):
    pending = add(library, verb="fry")
    approved = library.set_status(add(library).id, Status.APPROVED, by="ann")
    assert library.lookup("recipe", "fry", ("what",), approved_only=True) is None
    assert library.lookup("recipe", "fry", ("what",)) == pending
    assert library.lookup("recipe", "boil", ("what",), approved_only=True) == approved
    assert library.live("recipe", approved_only=True) == (approved,)
    assert library.live("recipe") == (pending, approved)


def test_a_rejected_entry_comes_back_only_while_its_action_has_no_other_live_entry(library):
    old = add(library)
    library.set_status(old.id, Status.REJECTED, by="ann")
    new = add(library, body="stir($what)")
    with pytest.raises(UserError, match=f"Entry {new.id} is already the live boil"):
        library.set_status(old.id, Status.APPROVED, by="ann")
    assert library.get(old.id).status == Status.REJECTED
    library.set_status(new.id, Status.REJECTED, by="ann")
    assert library.set_status(old.id, Status.APPROVED, by="ann").status == Status.APPROVED


def test_an_edit_is_a_new_version_and_goes_back_to_review(library):
    entry = library.set_status(add(library).id, Status.APPROVED, by="ann")
    edited = library.edit(entry.id, "pick_up($what)\nput($what, saucepan)", "bob", "passed", (), note="bigger pot")
    assert (edited.status, edited.reviewed_by, edited.reviewed_at) == (Status.PENDING, None, None)
    assert (edited.version, edited.body, edited.validation) == (2, "pick_up($what)\nput($what, saucepan)", "passed")
    assert (edited.model, edited.prompt_hash, edited.created) == (entry.model, entry.prompt_hash, entry.created)
    history = library.history(entry.id)
    assert [(v.version, v.author, v.note, v.body) for v in history] == [
        (1, "qwen", "learnt", entry.body), (2, "bob", "bigger pot", edited.body)]
    assert recent(history[1].at)


def test_undo_steps_back_one_version_at_a_time_and_keeps_every_version(library):
    entry = add(library, body="a($what)")
    library.edit(entry.id, "b($what)", "ann", "failed", ["line 1 b(egg): no such thing"])
    library.edit(entry.id, "c($what)", "ann")
    undone = library.undo(entry.id, "bob")
    assert (undone.body, undone.version, undone.validation, undone.problems) == (
        "b($what)", 4, "failed", ("line 1 b(egg): no such thing",))
    assert library.undo(entry.id, "bob").body == "a($what)"
    with pytest.raises(UserError, match="no earlier version"):
        library.undo(entry.id, "bob")
    history = library.history(entry.id)
    assert [(v.body, v.restores, v.author) for v in history] == [
        ("a($what)", None, "qwen"), ("b($what)", None, "ann"), ("c($what)", None, "ann"),
        ("b($what)", 2, "bob"), ("a($what)", 1, "bob")]
    assert history[3].note == "undo: back to version 2"


def test_a_new_entry_has_nothing_to_undo(library):
    entry = add(library)
    with pytest.raises(UserError, match="no earlier version") as raised:
        library.undo(entry.id, "ann")
    assert f"library history {entry.id}" in raised.value.hint
    assert library.history(entry.id)[-1].version == 1


@pytest.mark.parametrize("call", [
    lambda lib: lib.get(42), lambda lib: lib.history(42), lambda lib: lib.undo(42, "ann"),
    lambda lib: lib.edit(42, "stir($what)", "ann"), lambda lib: lib.set_status(42, Status.REJECTED, by="ann"),
])
def test_an_unknown_entry_is_a_user_error(library, call):
    with pytest.raises(UserError, match="No entry 42"):
        call(library)


def test_search_finds_verbs_and_bodies_and_follows_edits(library):
    boil = add(library, body="pick_up($what)\nput($what, pot)\ntoggle_on(stove_burner)")
    fry = add(library, verb="fry", body="put($what, pan)")
    assert library.search("pot") == (boil,)
    assert library.search("fry") == (fry,)
    assert {e.id for e in library.search("put")} == {boil.id, fry.id}
    assert library.search("pick_up") == (boil,) and library.search("stove*") == (boil,)
    assert library.search("boil OR pan") and len(library.search("boil OR pan")) == 2
    library.edit(fry.id, "put($what, skillet)", "ann")
    assert library.search("pan") == () and [e.id for e in library.search("skillet")] == [fry.id]
    assert library.search("  ") == library.entries()


@pytest.mark.parametrize("query", ['put($what', '"unclosed', "AND", "pot NOT"])
def test_a_bad_search_query_is_a_user_error(library, query):
    add(library)
    with pytest.raises(UserError, match="Cannot search") as raised:
        library.search(query)
    assert "double quotes" in raised.value.hint


def test_a_failing_edit_leaves_the_file_as_it_was(library, tmp_path):
    """The new version is written before the entry; the entry's update fails, and both are rolled back."""
    old = add(library)
    library.set_status(old.id, Status.REJECTED, by="ann")
    live = add(library, body="stir($what)")
    before = dump(tmp_path / "library.sqlite")
    with pytest.raises(UserError, match=f"Entry {live.id} is already the live"):
        library.edit(old.id, "whisk($what)", "bob")
    assert dump(tmp_path / "library.sqlite") == before
    assert len(library.history(old.id)) == 1 and library.search("whisk") == ()


def test_a_failing_transaction_writes_nothing(library, tmp_path):
    add(library)
    before = dump(tmp_path / "library.sqlite")
    with pytest.raises(RuntimeError), library.transaction():
        add(library, verb="fry")
        library.edit(1, "stir($what)", "ann")
        raise RuntimeError("power cut")
    assert dump(tmp_path / "library.sqlite") == before
    assert [e.verb for e in library.entries()] == ["boil"] and library.search("stir") == ()


def dump(path) -> list[str]:
    """Everything in the file, read by another connection."""
    conn = sqlite3.connect(path)
    lines = list(conn.iterdump())
    conn.close()
    return lines


def test_two_writers_at_once_wait_for_each_other_and_lose_nothing(library, tmp_path):
    """Another process (here a second connection in a thread) edits and replaces while this one does."""
    entry = add(library)
    other = Library(tmp_path / "library.sqlite")
    failures = []

    def work(store, name):
        try:
            for n in range(15):
                store.edit(entry.id, f"stir($what)\n# {name} {n}", name)
                current = store.lookup("recipe", f"{name}_verb", ("what",))
                store.add("recipe", f"{name}_verb", ("what",), f"shake($what)\n# {n}", "qwen", "h",
                          replacing=current.id if current else None)
        except Exception as error:  # noqa: BLE001 - the test reports any failure of a writer
            failures.append(error)

    workers = [threading.Thread(target=work, args=(store, name)) for store, name in ((library, "ann"), (other, "bob"))]
    for worker in workers:
        worker.start()
    for worker in workers:
        worker.join()
    other.close()
    assert failures == []
    assert [v.version for v in library.history(entry.id)] == list(range(1, 32))
    assert len(library.live("recipe")) == 3 and len(library.entries()) == 31


def test_every_review_is_logged_with_the_version_it_concerned(library):
    entry = add(library)
    library.set_status(entry.id, Status.APPROVED, by="ann")
    library.edit(entry.id, "stir($what)", "bob")  # the approval was of version 1: the entry is unreviewed again
    assert library.get(entry.id).reviewed_by is None
    library.set_status(entry.id, Status.REJECTED, by="cara")
    fresh = add(library, body="shake($what)")
    add(library, body="whisk($what)", replacing=fresh.id)
    assert [(r.version, r.status, r.reviewer) for r in library.reviews(entry.id)] == [
        (1, "approved", "ann"), (2, "rejected", "cara")]
    assert [(r.status, r.reviewer) for r in library.reviews(fresh.id)] == [("rejected", "cook2ltl")]
    assert all(recent(r.at) for r in library.reviews(entry.id))


def test_a_refused_review_is_not_logged(library):
    entry = add(library, validation="failed")
    with pytest.raises(UserError):
        library.set_status(entry.id, Status.APPROVED, by="ann")
    assert library.reviews(entry.id) == ()
