"""The app and the command line on one library file at the same time: the app translates (writing new entries)
while `cook2ltl library` approves and lists in another process; both succeed and the file stays whole."""

import asyncio
import os
import sqlite3
import sys

import pytest

from cook2ltl.library import Library, Status
from cook2ltl.ui.app import Cook2LTLApp
from cook2ltl.ui.services import Services
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel
from tests.reliability.processes import children, command_line, wait_until_gone

pytestmark = pytest.mark.anyio
RECIPE = "Boil the egg. Fry the potato."
SPANS = {"Boil the egg.": [("VERB", "Boil"), ("WHAT", "the egg")],
         "Fry the potato.": [("VERB", "Fry"), ("WHAT", "the potato")]}
ANSWERS = {"boil": "pick_up(egg)\nput(egg, pot)\nturn_on(stovetop)\nwait(egg == boiled)",
           "fry": "pick_up(potato)\nput(potato, pan)\nturn_on(stovetop)"}


@pytest.fixture
def anyio_backend() -> str:
    return "asyncio"


@pytest.fixture
def services(tmp_path, monkeypatch) -> Services:
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    monkeypatch.setenv("COOK2LTL_KITCHEN_CACHE", str(tmp_path / "kitchen-cache"))
    monkeypatch.delenv("COOK2LTL_THOR_EXECUTABLE", raising=False)

    def validator(primitives):
        from cook2ltl.execution.kitchen_check import KitchenValidator

        return KitchenValidator(primitives)

    def kitchen(scene):
        from cook2ltl.execution.launcher import start_embedded

        return start_embedded(scene)

    return Services(make_spans=lambda: ScriptedSpans(SPANS), make_dependencies=ScriptedDependencies,
                    make_model=lambda name: ScriptedModel(dict(ANSWERS)), library_path=tmp_path / "library.sqlite",
                    start_kitchen=kitchen, make_validator=validator, model_names=("scripted",))


async def cli(*arguments: str) -> tuple[int, str]:
    process = await asyncio.create_subprocess_exec(sys.executable, "-m", "cook2ltl", *arguments,
                                                   stdout=asyncio.subprocess.PIPE, stderr=asyncio.subprocess.PIPE)
    out, err = await process.communicate()
    return process.returncode, out.decode() + err.decode()


async def test_the_app_translates_while_the_cli_reviews_the_same_library(services):
    library = str(services.library_path)
    store = Library(services.library_path)
    whisk = store.add("recipe", "whisk", ("what",), "stir($what)", "m", "h")
    store.close()
    app = Cook2LTLApp(services, RECIPE)
    async with app.run_test(size=(120, 36)) as pilot:
        await pilot.press("ctrl+r")  # the app's worker writes the library from its own thread
        reviews = [cli("library", "approve", str(whisk.id), "--library", library, "--by", "carol"),
                   cli("library", "list", "--library", library)]
        results = await asyncio.gather(*reviews)
        await app.workers.wait_for_complete()
        await pilot.pause()
        assert app.translation is not None, "the app's translation did not finish"
    for code, output in results:
        assert code == 0 and "Traceback" not in output, output
    services.close()  # what the app does on quitting: its kitchen (of the kitchen check) ends with it
    kitchens = {pid for pid in children(os.getpid()) if "cook2ltl.execution.launcher" in command_line(pid)}
    assert wait_until_gone(kitchens, timeout=10) == set()
    store = Library(services.library_path)
    try:
        entries = {entry.verb: entry for entry in store.entries()}
        assert entries["whisk"].status == Status.APPROVED and entries["whisk"].reviewed_by == "carol"
        assert {"boil", "fry"} <= set(entries)  # what the app learnt meanwhile
    finally:
        store.close()
    with sqlite3.connect(library) as conn:
        assert conn.execute("PRAGMA integrity_check").fetchall() == [("ok",)]
