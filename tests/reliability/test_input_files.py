"""Every file a user can name is read with a bound: /dev/zero, a FIFO, a folder, a huge or binary file is a
clear UserError within seconds, never a hang or a full memory. And a primitive set, a kitchen file or an effect
table of the wrong shape is a one-line UserError naming the key, never a traceback."""

import io
import os
import sys
import threading
from pathlib import Path

import pytest

from cook2ltl.domain.settings_file import load_settings
from cook2ltl.errors import UserError
from cook2ltl.preprocess.recipe_file import read_recipe
from cook2ltl.reduce.primitives import load_primitives
from cook2ltl.world.effects import verb_table
from cook2ltl.world.pddl import load_domain
from cook2ltl.world.recipe_kitchen import read_kitchen

GOOD_SET = ("examples = 'e.txt'\nobjects = ['pot', 'stovetop']\nstates = ['boiled']\n"
            "[primitives]\nput = ['what', 'where']\nwait = ['condition']\n")
EXAMPLES = "def boil(water: what):\n    put(water, pot)\n    wait(water == boiled)\n"


def finishes(call, seconds: float = 20.0) -> BaseException | None:
    """What `call` raised (None if nothing), failing the test if it is still running after `seconds`."""
    outcome: list = []

    def run():
        try:
            call()
            outcome.append(None)
        except BaseException as error:  # noqa: BLE001 -- the test looks at it
            outcome.append(error)

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    thread.join(seconds)
    assert outcome, f"still reading after {seconds} s"
    return outcome[0]


def with_examples(folder: Path, examples: str) -> None:
    (folder / "set.toml").write_text(GOOD_SET.replace("'e.txt'", repr(examples)))


READERS = {
    "settings file": lambda path, folder: load_settings(path),
    "primitive set": lambda path, folder: load_primitives(str(path)),
    "examples file": lambda path, folder: (with_examples(folder, str(path)), load_primitives(str(folder / "set.toml"))),
    "PDDL domain": lambda path, folder: load_domain(path),
    "kitchen file": lambda path, folder: read_kitchen(path),
    "verb-effect table": lambda path, folder: verb_table(path),
    "recipe file": lambda path, folder: read_recipe(str(path), 1000),
}


def hostile_file(kind: str, folder: Path) -> Path:
    path = folder / kind
    if kind == "fifo":
        os.mkfifo(path)  # nobody writes: opening it to read would wait forever
    elif kind == "folder":
        path.mkdir()
    elif kind == "huge":
        with path.open("wb") as handle:
            handle.truncate(3 * 2**30)  # 3 GB of zeros, sparse: no disk used
    elif kind == "latin-1":
        path.write_bytes("name = 'crème brûlée'\n".encode("latin-1"))
    elif kind == "loop":
        path.symlink_to(path)
    elif kind == "under a file":
        (folder / "plain").write_text("x")
        path = folder / "plain" / "x"
    else:
        return Path({"dev-zero": "/dev/zero", "proc-mem": "/proc/self/mem"}[kind])
    return path


KINDS = ["dev-zero", "fifo", "folder", "huge", "latin-1", "loop", "under a file", "proc-mem"]
MESSAGES = {"dev-zero": "not a regular file", "fifo": "not a regular file", "folder": "it is a folder",
            "huge": "larger than the limit", "latin-1": "not UTF-8 text", "loop": "symbolic links",
            "under a file": "Not a directory", "proc-mem": "Cannot read"}


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("reader", READERS)
def test_a_file_that_cannot_be_text_is_refused_quickly(tmp_path, reader, kind):
    (tmp_path / "e.txt").write_text(EXAMPLES)
    path = hostile_file(kind, tmp_path)
    error = finishes(lambda: READERS[reader](path, tmp_path))
    assert isinstance(error, UserError), repr(error)
    assert MESSAGES[kind] in error.message and "\n" not in error.message, error.message


def test_standard_input_is_read_with_the_same_bound(monkeypatch):
    with open("/dev/zero", "rb") as zeros:
        monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(zeros))
        error = finishes(lambda: read_recipe("-", 1000))
    assert isinstance(error, UserError) and "larger than the limit of 1,000 bytes" in error.message


def test_a_domain_the_reader_cannot_parse_is_a_user_error(tmp_path):
    for number, text in enumerate(("(define (domain x) (:predicates", "(" * 5000, "\x01 not pddl")):
        (tmp_path / f"{number}.pddl").write_text(text)
        error = finishes(lambda: load_domain(tmp_path / f"{number}.pddl"))
        assert isinstance(error, UserError), repr(error)


def refused_set(tmp_path: Path, content: str) -> str:
    (tmp_path / "e.txt").write_text(EXAMPLES)
    (tmp_path / "set.toml").write_text(content, encoding="utf-8")
    with pytest.raises(UserError) as raised:
        load_primitives(str(tmp_path / "set.toml"))
    message = raised.value.message
    assert "\n" not in message and message.startswith(str(tmp_path / "set.toml")), message
    assert raised.value.hint
    return message


@pytest.mark.parametrize("change, expected", [
    (("objects = ['pot', 'stovetop']", "objects = 5"), "objects must be a list of at most 2000 lower-case"),
    (("objects = ['pot', 'stovetop']", "objects = ['pot', \"pot's\"]"), "objects[1] must be a lower-case identifier"),
    (("objects = ['pot', 'stovetop']", "objects = ['[bold]pot']"), "objects[0] must be a lower-case identifier"),
    (("objects = ['pot', 'stovetop']", "objects = ['Pot']"), "objects[0] must be a lower-case identifier"),
    (("states = ['boiled']", "states = 'boiled'"), "states must be a list of at most 500"),
    (("states = ['boiled']", "states = ['a\"b']"), "states[0] must be a lower-case identifier"),
    (("[primitives]\nput = ['what', 'where']\nwait = ['condition']\n", "primitives = 'x'\n"),
     "primitives must be a table of 1 to 200 primitives"),
    (("put = ['what', 'where']", "put = [1, 2]"), "[primitives] put[0] must be a lower-case identifier"),
    (("put = ['what', 'where']", "put = 2"), "[primitives] put must be a list of at most 8 parameter names"),
    (("put = ['what', 'where']", "'pick up' = ['what']"), "[primitives] has the key 'pick up', which must be"),
    (("put = ['what', 'where']", "put = ['what', 'where', 'how', 'a', 'b', 'c', 'd', 'e', 'f']"),
     "put must be a list of at most 8"),
    (("examples = 'e.txt'", "examples = 5"), "examples must be the file of the prompt's example functions"),
    (("examples = 'e.txt'", "examples = ''"), "examples must be the file of the prompt's example functions"),
    (("examples = 'e.txt'", "examples = 'e.txt'\nname = 'my robot'"), "name must be a name such as my-robot"),
    (("examples = 'e.txt'", "examples = 'e.txt'\nname = '[red]x[/red]'"), "name must be a name such as my-robot"),
    (("examples = 'e.txt'", "examples = 'e.txt'\ncolour = 'red'"), "unknown key colour (the file has name, "),
    (("examples = 'e.txt'", "examples = 'e.txt'\nworld = 5"), "world must be a table, not 5"),
    (("wait = ['condition']\n", "wait = ['condition']\n[world]\nkitchen = 'thor'"), "[world] domain is missing"),
    (("wait = ['condition']\n", "wait = ['condition']\n[world]\ndomain = 5"), "[world] domain must be the PDDL domain"),
    (("wait = ['condition']\n", "wait = ['condition']\n[world]\ndomain = '/dev/zero'"),
     "missing or not a regular file"),
    (("wait = ['condition']\n", "wait = ['condition']\n[world]\ndomain = 'd.pddl'\nplanner = 'yes'"),
     "[world] planner must be true or false, not 'yes'"),
    (("wait = ['condition']\n", "wait = ['condition']\n[world]\ndomain = 'd.pddl'\nliquids = 'Filled With'"),
     "[world] liquids must be a PDDL name"),
    (("wait = ['condition']\n", "wait = ['condition']\n[world]\ndomain = 'd.pddl'\nkit = 5"), "[world] kit must be"),
    (("wait = ['condition']\n", "wait = ['condition']\n[world]\ndomain = 'd.pddl'\nkit = {sliced = 'knife'}"),
     "[world.kit] sliced must be"),
    (("wait = ['condition']\n", "wait = ['condition']\n[world]\ndomain = 'd.pddl'\n[world.states]\n'very hot' = 'hot'"),
     "[world.states] has the key 'very hot', which must be a lower-case identifier"),
    (("wait = ['condition']\n", "wait = ['condition']\n[world]\ndomain = 'd.pddl'\nstates = [1]"),
     "[world] states must be a table of state words"),
])
def test_a_primitive_set_of_the_wrong_shape_names_the_key(tmp_path, change, expected):
    old, new = change
    assert old in GOOD_SET
    assert expected in refused_set(tmp_path, GOOD_SET.replace(old, new))


@pytest.mark.parametrize("content, expected", [
    pytest.param(GOOD_SET + "".join(f"p{i} = ['what']\n" for i in range(200)), "primitives must be a table of 1 "
                 "to 200", id="201 primitives"),
    pytest.param(GOOD_SET.replace("'pot', 'stovetop'", ", ".join(f"'o{i}'" for i in range(2001))),
                 "objects must be a list of at most 2000", id="2001 objects"),
    pytest.param(GOOD_SET.replace("'e.txt'", "'~no_such_user_here/e.txt'"), "cannot tell which home folder",
                 id="unknown home"),
    pytest.param(GOOD_SET.replace("'e.txt'", "'" + "e" * 300 + "'"), "is too long for a path", id="long name"),
    pytest.param(GOOD_SET.replace("'e.txt'", '"e\\u0000.txt"'), "holds a NUL byte", id="NUL"),
])
def test_a_primitive_set_is_bounded(tmp_path, content, expected):
    assert expected in refused_set(tmp_path, content)


def test_a_primitive_set_names_its_files_from_home(tmp_path, monkeypatch):
    monkeypatch.setenv("HOME", str(tmp_path))
    (tmp_path / "robot").mkdir()
    (tmp_path / "e.txt").write_text(EXAMPLES)
    (tmp_path / "robot" / "set.toml").write_text(GOOD_SET.replace("'e.txt'", "'~/e.txt'"))
    chosen = load_primitives("~/robot/set.toml")
    assert chosen.name == "set" and chosen.examples == EXAMPLES and chosen.source == tmp_path / "robot" / "set.toml"


@pytest.mark.parametrize("content, expected", [
    ("kinds = 5", "kinds must be a table of objects and their kinds"),
    ("[kinds]\npot = 'portable'", "[kinds] pot must be a list"),
    ("[kinds]\npot = ['portable']\n[start]\npot = 5", "[start] pot must be a kitchen object"),
    ("[kinds]\npot = ['portable']\n[ingredients]\nliquids = 'milk'", "[ingredients] liquids must be a list"),
    ("planning = []\n[kinds]\npot = ['portable']", "planning must be a table"),
    ("[start]\npot = ''", "kinds is missing"),
])
def test_a_kitchen_file_of_the_wrong_shape_names_the_key(tmp_path, content, expected):
    (tmp_path / "k.toml").write_text(content)
    with pytest.raises(UserError, match="k.toml: ") as raised:
        read_kitchen(tmp_path / "k.toml")
    assert expected in raised.value.message


@pytest.mark.parametrize("content", ["verbs = 5", "[verbs]\nboil = 'hot(what)'", "[verbs]\nboil = [5]", "x = 1"])
def test_an_effect_table_of_the_wrong_shape_is_a_user_error(tmp_path, content):
    (tmp_path / "effects.toml").write_text(content)
    with pytest.raises(UserError, match="effects.toml"):
        verb_table(tmp_path / "effects.toml")
