"""Nothing from a recipe, a library file or an import is ever run as code: a source audit, and hostile
bodies that are stored, imported, edited and looked up without ever running."""

import re
import subprocess
import sys

import pytest

from cook2ltl import paths
from cook2ltl.domain.actions import Source
from cook2ltl.library import Library
from cook2ltl.parse import parse_recipe
from cook2ltl.pipeline.records import TranslationFinished
from cook2ltl.pipeline.translator import Translator, translate
from cook2ltl.reduce.primitives import load_primitives
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel

SOURCE = paths.PROJECT_ROOT / "app" / "cook2ltl"
FORBIDDEN = {
    "eval": re.compile(r"(?<![\w.])eval\("),
    "exec": re.compile(r"(?<![\w.])exec\("),
    "compile": re.compile(r"(?<![\w.])compile\("),
    "__import__": re.compile(r"__import__\("),
    "pickle": re.compile(r"\bpickle\b|\bdill\b|\bcloudpickle\b|\bmarshal\b|\bshelve\b"),
    "yaml.load": re.compile(r"yaml\.(?:unsafe_)?load\("),
    "shell=True": re.compile(r"shell\s*=\s*True"),
    "os.system / popen": re.compile(r"os\.(?:system|popen|exec\w*|spawn\w*)\("),
    "torch.load without weights_only": re.compile(r"torch\.load\((?![^)]*weights_only\s*=\s*True)"),
    "trust_remote_code": re.compile(r"trust_remote_code\s*=\s*True"),
}
# The only modules that start programs, each with a fixed argument list (no user text reaches them as code).
SUBPROCESS_USERS = {"assembly/provision.py", "bench/micro.py", "bench/results.py", "bench/fuzz.py"}


def sources():
    return sorted(SOURCE.rglob("*.py"))


def test_no_source_file_evaluates_deserialises_or_shells_out():
    found = [f"{path.relative_to(SOURCE)}:{number}: {name}: {line.strip()}"
             for path in sources() for number, line in enumerate(path.read_text().splitlines(), 1)
             for name, pattern in FORBIDDEN.items() if pattern.search(line.split("#")[0])]
    assert found == []
    starting = {str(path.relative_to(SOURCE)) for path in sources() if re.search(r"\bsubprocess\b", path.read_text())}
    assert starting <= SUBPROCESS_USERS, starting - SUBPROCESS_USERS
    assert len(sources()) > 50  # the audit saw the package


def test_the_audit_would_catch_each_pattern():
    samples = {"eval": "eval(text)", "exec": "exec(body)", "compile": "compile(src, 'f', 'exec')",
               "__import__": "__import__('os')", "pickle": "import pickle", "yaml.load": "yaml.load(stream)",
               "shell=True": "run(cmd, shell=True)", "os.system / popen": "os.system(cmd)",
               "torch.load without weights_only": "torch.load(path)", "trust_remote_code": "trust_remote_code=True"}
    assert set(samples) == set(FORBIDDEN)
    for name, sample in samples.items():
        assert FORBIDDEN[name].search(sample), name
    assert not FORBIDDEN["eval"].search("model.eval()") and not FORBIDDEN["torch.load without weights_only"].search(
        "torch.load(f, map_location=d, weights_only=True)")


CODE_BODIES = (
    "__import__('os').system('touch {sentinel}')",
    "import os; os.system('touch {sentinel}')",
    "exec(open('{sentinel}', 'w').write('x'))",
    "system(touch_pwned)",  # reads as a call, of no primitive or library verb
    "pick_up($what)\n__import__('subprocess').run(['touch', '{sentinel}'])",
)
TEXT = "Boil the egg."
SPANS = {TEXT: [("VERB", "Boil"), ("WHAT", "the egg")]}
BOIL = "pick_up(egg)\nput(egg, pot)"


@pytest.mark.parametrize("body", CODE_BODIES)
def test_a_code_body_in_the_library_is_never_run_and_never_used(tmp_path, body):
    sentinel = tmp_path / "pwned"
    body = body.format(sentinel=sentinel)
    store = Library(tmp_path / "library.sqlite")
    bad = store.add("recipe", "boil", ("what",), body, "someone", "h")
    model = ScriptedModel({"boil": BOIL})
    recipe = parse_recipe(TEXT, ScriptedSpans(SPANS), ScriptedDependencies())
    events = list(translate(recipe, Translator(load_primitives("recipe"), model, store)))
    result = events[-1].translation.steps[0].actions[0]
    assert isinstance(events[-1], TranslationFinished)
    assert result.reduction.source == Source.LLM and model.calls == 1  # the stored body did not fit: reduced anew
    assert [call.text() for call in result.plan] == BOIL.splitlines()
    assert store.get(bad.id).status == "rejected"  # replaced by the new reduction
    store.close()
    assert not sentinel.exists()


def test_a_code_body_is_refused_by_library_edit(tmp_path):
    sentinel = tmp_path / "pwned"
    store = Library(tmp_path / "library.sqlite")
    entry = store.add("recipe", "boil", ("what",), "pick_up($what)", "m", "h")
    store.close()
    (tmp_path / "body.txt").write_text(f"__import__('os').system('touch {sentinel}')\nput($what, pot)\n")
    edited = subprocess.run([sys.executable, "-m", "cook2ltl", "library", "edit", str(entry.id), "--body-file",
                             str(tmp_path / "body.txt"), "--library", str(tmp_path / "library.sqlite"),
                             "--no-validate"], capture_output=True, text=True, timeout=120)
    assert edited.returncode == 2 and "Traceback" not in edited.stderr and "nothing saved" in edited.stderr
    assert Library(tmp_path / "library.sqlite").get(entry.id).body == "pick_up($what)"
    assert not sentinel.exists()
