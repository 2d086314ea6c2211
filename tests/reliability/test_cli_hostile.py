"""The real command line on hostile recipes: a clear one-line error and exit code 2, or a normal result."""

import json
import subprocess
import sys

import pytest

from tests.reliability.hostile import TRIED

ODD = ("\u202eBoil the eggs.\u202c Add s\u200balt to the pot 🍳🍳.\n"
       "Stir the sauce\u0301\u0301\u0301 gently. \ufeffMix.\nAjoutez le sel. 加盐。")


def cook2ltl(*arguments: str, stdin: bytes | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "cook2ltl", *arguments], input=stdin, capture_output=True,
                          timeout=300)


REFUSED = {
    "empty": (b"", "The recipe is empty"),
    "whitespace only": (b"  \n\t\n   ", "The recipe is empty"),
    "binary": (bytes(range(256)) * 8, "looks binary"),
    "latin-1": ("Crème brûlée: caramelise the sugar.".encode("latin-1"), "is not UTF-8 text"),
    "one megabyte": (b"Boil the eggs. " * 70_000, "larger than the limit of 200,000 bytes"),
    "ten thousand steps": (b"Stir.\n" * 10_000, "10,000 steps; the limit is 500"),
}


@pytest.mark.parametrize("name", REFUSED)
@pytest.mark.parametrize("command", ["parse", "translate"])
def test_hostile_recipe_files_are_refused_clearly(tmp_path, name, command):
    TRIED["hand-made cli (real)"] += 1
    data, message = REFUSED[name]
    (tmp_path / "recipe.txt").write_bytes(data)
    translating = ["--library", str(tmp_path / "l.sqlite"), "--model", "smollm2-135m", "--no-validate"]
    result = cook2ltl(command, str(tmp_path / "recipe.txt"), *(translating if command == "translate" else []))
    err = result.stderr.decode()
    assert result.returncode == 2 and "Traceback" not in err, err
    assert err.startswith("error: ") and message in " ".join(err.split()), err


def test_binary_on_standard_input_is_refused(tmp_path):
    TRIED["hand-made cli (real)"] += 1
    result = cook2ltl("parse", "-", stdin=b"\x7fELF\x02\x01\x01\x00" + bytes(500))
    assert result.returncode == 2 and b"standard input looks binary" in result.stderr


def test_odd_unicode_parses_into_clean_steps(tmp_path):
    TRIED["hand-made cli (real)"] += 1
    (tmp_path / "recipe.txt").write_text(ODD, encoding="utf-8")
    result = cook2ltl("parse", str(tmp_path / "recipe.txt"), "--json")
    assert result.returncode == 0, result.stderr.decode()
    text = result.stdout.decode()
    for hidden in ("\u202e", "\u202c", "\u200b", "\ufeff"):
        assert hidden not in text  # shown as spaces: no reordering, no invisible word breaks
    steps = json.loads(text)["steps"]
    assert len(steps) >= 4
    for step in steps:
        for span in step["spans"]:  # no span of marks or emoji alone
            assert any(ch.isalnum() for ch in span["text"]), span
        for frame in step["frames"]:
            assert any(ch.isalnum() for ch in frame["verb"]["text"]), frame
