"""Each library entry keeps its intended effect: stored, migrated, edited, shown, exported and imported."""

import json
import os
import sqlite3
import subprocess
import sys

import pytest
from sqlite_utils import Database
from typer.testing import CliRunner

from cook2ltl.errors import UserError
from cook2ltl.library import SCHEMA_VERSION, Library, Status
from cook2ltl.library.exchange import export_library, import_library
from cook2ltl.library.schema import MIGRATIONS
from cook2ltl.world.effects import parse_template, verb_table

BOIL = "pick_up($what)\nput($what, pot)"
BLANCH = "put($what, pot)\nwait($what == hot)"


@pytest.fixture
def library(tmp_path):
    store = Library(tmp_path / "library.sqlite")
    yield store
    store.close()


def dump(path) -> list[str]:
    with sqlite3.connect(path) as conn:
        return list(conn.iterdump())


def test_the_table_and_the_library_read_atoms_with_one_parser():
    assert parse_template(" in(what,  fridge) ") == ("in", ("what", "fridge"))
    assert verb_table()["refrigerate"] == (("cold", ("what",)), ("in", ("what", "fridge")))
    for bad in ("boiled", "Boiled(what)", "boiled(what", "done(what)", "ready(what)", ""):
        with pytest.raises(ValueError):
            parse_template(bad)


def test_a_version_3_library_migrates_in_place_with_no_effect_recorded(tmp_path):
    path = tmp_path / "v3.sqlite"
    conn = sqlite3.connect(path)
    db = Database(conn)
    conn.execute("BEGIN")
    for migration in MIGRATIONS[:3]:  # the schema as released before effects were kept
        migration(db)
    conn.execute("PRAGMA user_version = 3")
    db["actions"].insert({"primitives": "recipe", "verb": "boil", "signature": "what", "body": BOIL,
                          "status": "approved", "model": "qwen", "prompt_hash": "a", "created": "2026-01-02T03:04:05"})
    conn.execute("COMMIT")
    conn.close()
    store = Library(path)
    [entry] = store.entries()
    assert (entry.verb, entry.body, entry.status, entry.effect) == ("boil", BOIL, Status.APPROVED, None)
    store.close()
    with sqlite3.connect(path) as conn:
        assert conn.execute("PRAGMA user_version").fetchone()[0] == SCHEMA_VERSION == 4


def test_an_effect_is_stored_written_one_way_and_read_back(library):
    boil = library.add("recipe", "boil", ("what",), BOIL, "qwen", "h",
                       effect=["boiled( what )", "in(what,pot)", "boiled(what)"])
    peel = library.add("recipe", "peel", ("what",), "pick_up($what)", "qwen", "h", effect=[])
    old = library.add("recipe", "fry", ("what",), "put($what, pan)", "qwen", "h")
    assert boil.effect == ("boiled(what)", "in(what, pot)") == library.get(boil.id).effect
    assert library.lookup("recipe", "boil", ("what",)).effect == boil.effect
    assert (library.get(peel.id).effect, library.get(old.id).effect) == ((), None)  # nothing to reach ≠ not recorded


@pytest.mark.parametrize("effect, message", [(["done(what)"], "done is never an effect"),
                                             (["boiled"], "'boiled' is not an effect atom"),
                                             (["boiled(what)", "hot(what); drop table"], "is not an effect atom")])
def test_a_bad_effect_is_refused_with_a_clear_message_and_nothing_written(library, effect, message):
    entry = library.add("recipe", "fry", ("what",), "put($what, pan)", "qwen", "h", effect=["fried(what)"])
    before = dump(library.path)
    with pytest.raises(UserError, match=message) as refused:
        library.add("recipe", "boil", ("what",), BOIL, "qwen", "h", effect=effect)
    assert "boiled(what)" in refused.value.hint
    with pytest.raises(UserError, match=message):
        library.edit(entry.id, "put($what, skillet)", "ann", effect=effect)
    assert dump(library.path) == before


def test_an_edit_keeps_or_sets_the_effect_and_the_history_tells(library):
    entry = library.add("recipe", "blanch", ("what",), BOIL, "qwen", "h", effect=["hot(what)"])
    library.set_status(entry.id, Status.APPROVED, by="ann")
    assert library.edit(entry.id, BLANCH, "bob").effect == ("hot(what)",)  # no effect given: kept
    edited = library.edit(entry.id, BLANCH, "bob", note="cooked too", effect=["cooked(what)", "in(what, pot)"])
    assert (edited.effect, edited.version, edited.status) == (("cooked(what)", "in(what, pot)"), 3, Status.PENDING)
    assert library.history(entry.id)[-1].note == "cooked too; effect: cooked(what), in(what, pot)"
    assert library.undo(entry.id, "bob").effect == edited.effect  # undo brings a body back, not an effect
    assert library.edit(entry.id, BLANCH, "bob", effect=None).effect is None


def test_export_and_import_keep_effects(library, tmp_path):
    library.add("recipe", "boil", ("what",), BOIL, "qwen", "h", effect=["boiled(what)"])
    library.add("recipe", "peel", ("what",), "pick_up($what)", "qwen", "h", effect=[])
    library.add("recipe", "fry", ("what",), "put($what, pan)", "qwen", "h")
    export_library(library, tmp_path / "lab.json")
    assert [e["effect"] for e in json.loads((tmp_path / "lab.json").read_text())["entries"]] == [
        ["boiled(what)"], [], None]
    other = Library(tmp_path / "other.sqlite")
    assert len(import_library(other, tmp_path / "lab.json", "cara").added) == 3
    assert [e.effect for e in other.entries()] == [("boiled(what)",), (), None]
    assert len(import_library(other, tmp_path / "lab.json", "cara").unchanged) == 3
    other.close()


def test_an_older_export_without_effects_imports_and_leaves_effects_here_alone(library, tmp_path):
    library.add("recipe", "boil", ("what",), BOIL, "qwen", "h")
    export_library(library, tmp_path / "lab.json")
    data = json.loads((tmp_path / "lab.json").read_text())
    data["schema_version"] = 3
    del data["entries"][0]["effect"]
    (tmp_path / "old.json").write_text(json.dumps(data))
    other = Library(tmp_path / "other.sqlite")
    assert len(import_library(other, tmp_path / "old.json", "cara").added) == 1
    assert other.get(1).effect is None
    other.edit(1, BOIL, "dan", effect=["boiled(what)"])
    assert len(import_library(other, tmp_path / "old.json", "cara").unchanged) == 1
    assert other.get(1).effect == ("boiled(what)",)
    other.close()


def test_another_effect_in_an_import_is_a_conflict_or_replaces_a_pending_entry(library, tmp_path):
    library.add("recipe", "boil", ("what",), BOIL, "qwen", "h", effect=["boiled(what)"])
    export_library(library, tmp_path / "lab.json")
    other = Library(tmp_path / "other.sqlite")
    mine = other.add("recipe", "boil", ("what",), BOIL, "qwen", "h", effect=["hot(what)"])
    report = import_library(other, tmp_path / "lab.json", "cara")
    assert report.conflicts == (f"recipe boil(what): entry {mine.id} is pending here with another effect; kept "
                                "(--replace-pending adds the file's effect to it as a new version)",)
    replaced = import_library(other, tmp_path / "lab.json", "cara", replace_pending=True)
    assert replaced.replaced and other.get(mine.id).effect == ("boiled(what)",)
    other.set_status(mine.id, Status.APPROVED, by="dan")
    other.edit(mine.id, BOIL, "dan", effect=["hot(what)"])
    other.set_status(mine.id, Status.APPROVED, by="dan")
    approved = import_library(other, tmp_path / "lab.json", "cara", replace_pending=True)
    assert approved.conflicts == (f"recipe boil(what): entry {mine.id} is approved here with another effect; kept",)
    other.close()


@pytest.mark.parametrize("effect, message", [("boiled(what)", '"effect": must be a list, not "boiled'),
                                             ([1], '"effect" item 1: must be a string, not 1'),
                                             (["ready(what)"], 'entry 2: "effect": \'ready\\(what\\)\': ready is')])
def test_a_malformed_effect_in_an_import_is_refused_before_anything_is_written(library, tmp_path, effect, message):
    library.add("recipe", "boil", ("what",), BOIL, "qwen", "h", effect=["boiled(what)"])
    library.add("recipe", "fry", ("what",), "put($what, pan)", "qwen", "h")
    export_library(library, tmp_path / "lab.json")
    data = json.loads((tmp_path / "lab.json").read_text())
    data["entries"][1]["effect"] = effect
    (tmp_path / "bad.json").write_text(json.dumps(data))
    other = Library(tmp_path / "other.sqlite")
    before = dump(other.path)
    with pytest.raises(UserError, match=message):
        import_library(other, tmp_path / "bad.json", "cara")
    assert dump(other.path) == before  # the good first entry is not written either
    other.close()


def test_show_and_edit_on_the_command_line(library):
    from cook2ltl.cli import app

    entry = library.add("recipe", "blanch", ("what",), BOIL, "qwen", "h")
    runner, where = CliRunner(env={"COLUMNS": "200"}), ["--library", str(library.path), "--by", "ann"]
    show = ["library", "show", str(entry.id), "--library", str(library.path)]
    assert "effect: not recorded" in runner.invoke(app, show).output
    edited = runner.invoke(app, ["library", "edit", str(entry.id), "--effect", "hot(what)", "--effect",
                                 "in(what,pot)", *where])
    assert edited.exit_code == 0, edited.output
    assert "version 2, kitchen check unchecked, effect hot(what), in(what, pot)" in edited.output
    assert "effect: hot(what), in(what, pot)" in runner.invoke(app, show).output
    body_only = runner.invoke(app, ["library", "edit", str(entry.id), "--body-file", "-", "--no-validate", *where],
                              input=BLANCH)
    assert body_only.exit_code == 0 and library.get(entry.id).effect == ("hot(what)", "in(what, pot)")
    same = runner.invoke(app, ["library", "edit", str(entry.id), "--effect", "hot(what)", "--effect",
                               "in(what, pot)", *where])
    assert "unchanged; nothing saved" in same.output and library.get(entry.id).version == 3
    assert runner.invoke(app, ["library", "edit", str(entry.id), "--effect", "none", *where]).exit_code == 0
    assert "effect: none (nothing to reach)" in runner.invoke(app, show).output
    assert runner.invoke(app, ["library", "edit", str(entry.id), "--clear-effect", *where]).exit_code == 0
    assert library.get(entry.id).effect is None
    for refused in (["--effect", "done(what)"], ["--effect", "hot(what)", "--clear-effect"], []):
        result = runner.invoke(app, ["library", "edit", str(entry.id), *refused, *where])
        assert isinstance(result.exception, UserError), result.output
    assert library.get(entry.id).version == 5


def test_a_bad_effect_on_the_command_line_is_a_clear_error_and_saves_nothing(library):
    library.add("recipe", "boil", ("what",), BOIL, "qwen", "h", effect=["boiled(what)"])
    before = dump(library.path)
    result = subprocess.run([sys.executable, "-m", "cook2ltl", "library", "edit", "1", "--effect", "[red]hot[/red]",
                             "--library", str(library.path)], capture_output=True, text=True, timeout=120,
                            env={**os.environ, "COOK2LTL_USER": "ann", "COLUMNS": "200"})
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert "--effect: '[red]hot[/red]' is not an effect atom" in result.stderr  # printed as text, not markup
    assert dump(library.path) == before
