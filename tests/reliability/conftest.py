import json
import os
from pathlib import Path

import pytest

from tests.models_required import require_models
from tests.reliability.hostile import TRIED


@pytest.fixture(scope="session")
def real_parsers():
    from cook2ltl.assembly.backends import dependency_parser, span_extractor
    from cook2ltl.domain.settings import Settings

    require_models("gliner-cook2ltl", "spacy-sm")
    return span_extractor(Settings()), dependency_parser()


def pytest_terminal_summary(terminalreporter):
    counts_file = os.environ.get("COOK2LTL_FUZZ_COUNTS")  # `cook2ltl bench fuzz` reads the counts from here
    if counts_file:
        Path(counts_file).write_text(json.dumps(dict(TRIED)), encoding="utf-8")
    if TRIED:
        counts = ", ".join(f"{name} {count}" for name, count in sorted(TRIED.items()))
        terminalreporter.write_line(f"reliability: inputs tried: {sum(TRIED.values())} ({counts})")
