"""The app with fake parsers and a scripted model (tests/fakes.py, tests/reduce/fake_model.py), a real SQLite
library in tmp_path and, for rollouts, the real embedded kitchen behind ai2thor's Controller."""

from __future__ import annotations

from pathlib import Path

import pytest

from cook2ltl.domain.settings import TranslateSettings
from cook2ltl.ui.app import Cook2LTLApp
from cook2ltl.ui.services import Services
from tests.fakes import ScriptedDependencies, ScriptedSpans
from tests.reduce.fake_model import ScriptedModel

SIZE = (120, 36)
RECIPE = "Boil the egg. Put the egg in a bowl. Boil the potato."
FRIDGE_RECIPE = "Refrigerate the apple."
SPANS = {
    "Boil the egg.": [("VERB", "Boil"), ("WHAT", "the egg")],
    "Put the egg in a bowl.": [("VERB", "Put"), ("WHAT", "the egg"), ("WHERE", "a bowl")],
    "Boil the potato.": [("VERB", "Boil"), ("WHAT", "the potato")],
    "Refrigerate the apple.": [("VERB", "Refrigerate"), ("WHAT", "the apple")],
}
# A first plan the kitchen refuses (the pot is put down before anything holds it), for the repair.
BOIL_UNHELD = "put(egg, pot)\nturn_on(stovetop)"
ANSWERS = {
    "boil": "pick_up(pot)\nput(pot, stovetop)\npick_up(egg)\nput(egg, pot)\nturn_on(stovetop)\nwait(egg == boiled)",
    "refrigerate": "open(fridge)\npick_up(apple)\nput(apple, fridge)\nclose(fridge)",
}


class Counting:
    """A factory that counts its calls: the app must build nothing heavy before a run needs it."""

    def __init__(self, build) -> None:
        self.build, self.calls, self.built = build, 0, []

    def __call__(self, *args):
        self.calls += 1
        self.built.append(self.build(*args))
        return self.built[-1]

    def stopped_all(self) -> bool:
        """For kitchens: every player process it started has ended."""
        return all(k.server is None or k.server.unity_proc.poll() is not None for k in self.built)


@pytest.fixture
def sandbox(tmp_path, monkeypatch) -> Path:
    """HOME, the user data folder and the kitchen's cache in tmp_path (the Controller writes ~/.ai2thor)."""
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    monkeypatch.setenv("COOK2LTL_DATA", str(tmp_path / "data"))
    monkeypatch.setenv("COOK2LTL_KITCHEN_CACHE", str(tmp_path / "kitchen-cache"))
    monkeypatch.setenv("COOK2LTL_USER", "tester")
    monkeypatch.delenv("COOK2LTL_THOR_EXECUTABLE", raising=False)
    return tmp_path


@pytest.fixture
def model() -> ScriptedModel:
    return ScriptedModel(dict(ANSWERS))


@pytest.fixture
def services(sandbox, model) -> Services:
    def kitchen(scene: str):
        from cook2ltl.execution.launcher import start_embedded

        return start_embedded(scene)

    def validator(primitives):
        from cook2ltl.execution.kitchen_check import KitchenValidator

        return KitchenValidator(primitives)

    return Services(
        make_spans=Counting(lambda: ScriptedSpans(SPANS)),
        make_dependencies=Counting(ScriptedDependencies),
        make_model=Counting(lambda name: model),
        library_path=sandbox / "library.sqlite",
        start_kitchen=Counting(kitchen),
        make_validator=Counting(validator),
        model_names=(model.name,),
    )


@pytest.fixture
def make_app(services):
    def make(text: str = RECIPE, **kwargs) -> Cook2LTLApp:
        # the app's wiring of the kitchen check, repairs and cancelling, as without the world model
        kwargs.setdefault("translate", TranslateSettings(ground=False))
        return Cook2LTLApp(services, text, **kwargs)

    return make


@pytest.fixture
def anyio_backend() -> str:
    """The async tests run on asyncio (anyio's pytest plugin; Textual runs on asyncio)."""
    return "asyncio"


async def settle(pilot) -> None:
    """Wait for every worker to end (a failed one included: the app shows its dialog; a cancelled one too: an
    exclusive worker is cancelled when a newer one replaces it), then for the messages they posted to be
    handled."""
    from textual.worker import WorkerCancelled, WorkerFailed

    try:
        await pilot.app.workers.wait_for_complete()
    except (WorkerFailed, WorkerCancelled):
        pass
    await pilot.pause()
    await pilot.pause()  # the tables lay their columns out on the refresh after the messages

def text(widget) -> str:
    return str(widget.render())


def rows(screen, table: str) -> list[list[str]]:
    from textual.widgets import DataTable

    found = screen.query_one(table, DataTable)
    return [[str(cell) for cell in found.get_row_at(i)] for i in range(found.row_count)]


def once(messages: list) -> list:
    """Each message once: the hook sees a message more than once on its way."""
    return list({id(m): m for m in messages}.values())
