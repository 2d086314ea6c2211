"""Export and import of the action library as JSON: round trips, conflicts, and bad files refused whole."""

import json
import sqlite3

import pytest

from cook2ltl.errors import UserError
from cook2ltl.library import SCHEMA_VERSION, Library, Status
from cook2ltl.library.exchange import export_library, import_library


@pytest.fixture
def source(tmp_path):
    library = Library(tmp_path / "source.sqlite")
    boil = library.add("recipe", "boil", ("what",), "pick_up($what)\nput($what, pot)", "qwen", "h1",
                       validation="passed", example={"$what": "egg"})
    library.edit(boil.id, "pick_up($what)\nput($what, saucepan)", "bob", "passed", (), note="bigger")
    library.set_status(boil.id, Status.APPROVED, by="ann")
    library.add("recipe", "fry", ("what", "where"), "put($what, $where)", "qwen", "h2", validation="failed",
                problems=["line 1 put(egg, pan): not holding egg"])
    rejected = library.add("ai2thor", "rinse", (), "toggle_on(faucet)", "smollm", "h3")
    library.set_status(rejected.id, Status.REJECTED, by="ann")
    yield library
    library.close()


@pytest.fixture
def target(tmp_path):
    library = Library(tmp_path / "target.sqlite")
    yield library
    library.close()


def test_export_writes_every_entry_with_its_history(source, tmp_path):
    path = tmp_path / "lab.json"
    assert export_library(source, path) == 3
    data = json.loads(path.read_text())
    assert data["schema_version"] == SCHEMA_VERSION
    boil = data["entries"][0]
    assert (boil["verb"], boil["signature"], boil["status"], boil["reviewed_by"], boil["example"]) == (
        "boil", ["what"], "approved", "ann", {"$what": "egg"})
    assert [(v["version"], v["author"], v["note"]) for v in boil["history"]] == [(1, "qwen", "learnt"),
                                                                                 (2, "bob", "bigger")]
    assert not list(tmp_path.glob(".lab.json.*"))  # no temporary file left behind


def test_a_round_trip_keeps_entries_reviews_and_histories(source, target, tmp_path):
    path = tmp_path / "lab.json"
    export_library(source, path)
    report = import_library(target, path, by="cara")
    assert report.added == ("recipe boil(what)", "recipe fry(what, where)", "ai2thor rinse()")
    assert (report.unchanged, report.replaced, report.conflicts) == ((), (), ())
    for mine, theirs in zip(source.entries(), target.entries()):
        for field in ("primitives", "verb", "signature", "body", "status", "model", "prompt_hash", "created",
                      "validation", "problems", "reviewed_by", "reviewed_at", "example"):
            assert getattr(mine, field) == getattr(theirs, field), field
        mine_history, their_history = source.history(mine.id), target.history(theirs.id)
        assert [(v.version, v.body, v.author, v.at, v.note) for v in mine_history] == [
            (v.version, v.body, v.author, v.at, v.note) for v in their_history[:-1]]
        stamp = their_history[-1]
        assert (stamp.author, stamp.note, stamp.body, theirs.version) == (
            "cara", "imported from lab.json", mine.body, mine.version + 1)
    assert target.lookup("recipe", "boil", ("what",), approved_only=True).body.endswith("saucepan)")
    assert target.lookup("ai2thor", "rinse", ()) is None
    assert {e.verb for e in target.search("saucepan OR faucet")} == {"boil", "rinse"}  # the index follows imports
    for mine, theirs in zip(source.entries(), target.entries()):
        assert [(r.version, r.status, r.reviewer, r.at) for r in source.reviews(mine.id)] == [
            (r.version, r.status, r.reviewer, r.at) for r in target.reviews(theirs.id)]
    assert [(r.version, r.reviewer) for r in target.reviews(1)] == [(2, "ann")]


def test_an_export_from_before_the_review_log_is_read(source, target, tmp_path):
    data = good_export(tmp_path, source)
    data["schema_version"] = 2
    for entry in data["entries"]:
        del entry["reviews"]
    path = tmp_path / "old.json"
    path.write_text(json.dumps(data))
    assert len(import_library(target, path, by="cara").added) == 3
    assert target.get(1).reviewed_by == "ann" and target.reviews(1) == ()


def test_importing_the_same_file_again_changes_nothing(source, target, tmp_path):
    path = tmp_path / "lab.json"
    export_library(source, path)
    import_library(target, path, by="cara")
    before = dump(target)
    report = import_library(target, path, by="cara")
    assert report.added == () and len(report.unchanged) == 3
    assert dump(target) == before


def test_an_approved_entry_is_never_overwritten(source, target, tmp_path):
    mine = target.add("recipe", "boil", ("what",), "stir($what)", "qwen", "x")
    target.set_status(mine.id, Status.APPROVED, by="dan")
    export_library(source, tmp_path / "lab.json")
    report = import_library(target, tmp_path / "lab.json", by="cara", replace_pending=True)
    assert report.conflicts == (f"recipe boil(what): entry {mine.id} is approved here with another body; kept",)
    assert target.get(mine.id) == target.lookup("recipe", "boil", ("what",))
    assert (target.get(mine.id).body, len(target.history(mine.id))) == ("stir($what)", 1)


def test_a_pending_entry_is_replaced_only_when_asked(source, target, tmp_path):
    mine = target.add("recipe", "boil", ("what",), "stir($what)", "qwen", "x")
    export_library(source, tmp_path / "lab.json")
    kept = import_library(target, tmp_path / "lab.json", by="cara")
    assert "--replace-pending" in kept.conflicts[0] and target.get(mine.id).body == "stir($what)"
    replaced = import_library(target, tmp_path / "lab.json", by="cara", replace_pending=True)
    assert replaced.replaced == (f"recipe boil(what) (entry {mine.id})",)
    entry = target.get(mine.id)
    assert (entry.body, entry.status, entry.version, entry.validation) == (
        "pick_up($what)\nput($what, saucepan)", Status.PENDING, 2, "passed")
    assert target.history(mine.id)[-1].author == "cara"


def test_rejections_travel_but_never_touch_a_live_entry_silently(source, target, tmp_path):
    mine = target.add("ai2thor", "rinse", (), "toggle_on(faucet)", "qwen", "x")  # the body the file rejects
    refused = target.add("recipe", "fry", ("what", "where"), "put($what, $where)", "qwen", "x")
    target.set_status(refused.id, Status.REJECTED, by="dan")  # the body the file brings, pending
    export_library(source, tmp_path / "lab.json")
    report = import_library(target, tmp_path / "lab.json", by="cara")
    assert report.added == ("recipe boil(what)",)
    assert report.conflicts == (
        f"recipe fry(what, where): entry {refused.id} rejected this body here; kept rejected",
        f"ai2thor rinse(): the file rejects the body of entry {mine.id}, pending here; review it")
    assert target.get(mine.id).status == Status.PENDING and target.get(refused.id).status == Status.REJECTED
    assert target.lookup("recipe", "fry", ("what", "where")) is None


def good_export(tmp_path, source):
    path = tmp_path / "lab.json"
    export_library(source, path)
    return json.loads(path.read_text())


def broken(data, change):
    change(data)
    return json.dumps(data)


@pytest.mark.parametrize("write, message", [
    (lambda d: '{"schema_version": 2, "entries": [', "not valid JSON: .* line 1, column"),
    (lambda d: "[1, 2]", 'no "schema_version"'),
    (lambda d: broken(d, lambda x: x.update(schema_version=1)), "schema version 1; this cook2ltl reads versions 2 to"),
    (lambda d: broken(d, lambda x: x.update(schema_version="2")), 'schema version "2"'),
    (lambda d: broken(d, lambda x: x.update(entries={})), '"entries" must be a list'),
    (lambda d: broken(d, lambda x: x["entries"].append(7)), "entry 4 is not a JSON object"),
    (lambda d: broken(d, lambda x: x["entries"][2].update(status="maybe")),
     'entry 3, "status": must be one of \'pending\', \'approved\' or \'rejected\', not "maybe"'),
    (lambda d: broken(d, lambda x: x["entries"][1].pop("verb")), 'entry 2, "verb": is missing'),
    (lambda d: broken(d, lambda x: x["entries"][1].update(signature="what")), '"signature": must be a list, not "what"'),
    (lambda d: broken(d, lambda x: x["entries"][1].update(problems=[1])), '"problems" item 1: must be a string, not 1'),
    (lambda d: broken(d, lambda x: x["entries"][1].update(created="yesterday")), '"created": must be an ISO 8601 time, not "yesterday"'),
    (lambda d: broken(d, lambda x: x["entries"][1].update(example={"what": "egg"})), '"example", "what": must be a name such as \\$what'),
    (lambda d: broken(d, lambda x: x["entries"][0].update(validation="ok")), '"validation": must be one of'),
    (lambda d: broken(d, lambda x: x["entries"][0].update(body="rm -rf /")), "not a call: 'rm -rf /'"),
    (lambda d: broken(d, lambda x: x["entries"][0].update(history=[])), '"history": must have at least 1 item'),
    (lambda d: broken(d, lambda x: x["entries"][0]["history"].reverse()), "must go up in version numbers"),
    (lambda d: broken(d, lambda x: x["entries"][0]["history"][1].update(version=True)),
     '"history" item 2, "version": must be a whole number, not true'),
    (lambda d: broken(d, lambda x: x["entries"][0]["reviews"][0].update(version=7)),
     'entry 1: a review names version 7, which is not in the entry\'s "history"'),
    (lambda d: broken(d, lambda x: x["entries"][0]["reviews"][0].update(reviewer="")), '"reviews" item 1, "reviewer": is empty'),
])
def test_a_bad_file_is_refused_whole_with_a_clear_message(source, target, tmp_path, write, message):
    data = good_export(tmp_path, source)
    target.add("recipe", "stew", ("what",), "stir($what)", "qwen", "x")
    path = tmp_path / "bad.json"
    path.write_text(write(data))
    before = dump(target)
    with pytest.raises(UserError, match=message) as raised:
        import_library(target, path, by="cara")
    assert "bad.json" in raised.value.message and raised.value.hint
    assert dump(target) == before


def test_a_file_that_is_not_text_or_not_there_is_a_clear_error(target, tmp_path):
    binary = tmp_path / "photo.json"
    binary.write_bytes(bytes(range(256)))
    with pytest.raises(UserError, match="is not UTF-8 text"):
        import_library(target, binary, by="cara")
    with pytest.raises(UserError, match="No export file at"):
        import_library(target, tmp_path / "missing.json", by="cara")
    assert target.entries() == ()


def test_a_failure_half_way_through_an_import_writes_nothing(source, target, tmp_path, monkeypatch):
    export_library(source, tmp_path / "lab.json")
    before = dump(target)
    calls = []

    def failing_insert(entry, history, reviews):
        if calls:
            raise sqlite3.OperationalError("disk I/O error")
        calls.append(entry)
        return Library.insert(target, entry, history, reviews)

    monkeypatch.setattr(target, "insert", failing_insert)
    with pytest.raises(UserError, match="disk I/O error"):
        import_library(target, tmp_path / "lab.json", by="cara")
    assert calls and dump(target) == before


def test_export_to_a_folder_is_a_clear_error(source, tmp_path):
    with pytest.raises(UserError, match="Cannot write"):
        export_library(source, tmp_path)
    assert not list(tmp_path.glob(".*.tmp"))


def dump(library) -> list[str]:
    conn = sqlite3.connect(library.path)
    lines = list(conn.iterdump())
    conn.close()
    return lines


@pytest.mark.parametrize("text, message", [
    ("[" * 100_000 + "]" * 100_000, "nests too deeply"),
    ('{"schema_version": 1' + "0" * 5000 + ', "entries": []}', "integer string conversion"),
    ('{"schema_version": 3, "entries": [{"verb": "bo\\udcffil"}]}', "not Unicode .*lone surrogate"),
])
def test_json_that_python_reads_but_cannot_use_is_a_clear_error(target, tmp_path, text, message):
    path = tmp_path / "hostile.json"
    path.write_text(text)
    with pytest.raises(UserError, match=message):
        import_library(target, path, by="cara")
    assert target.entries() == ()
