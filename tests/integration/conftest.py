import pytest

from tests.models_required import require_models


@pytest.fixture(scope="session")
def real_parsers():
    from cook2ltl.assembly.backends import dependency_parser, span_extractor
    from cook2ltl.domain.settings import Settings

    require_models("gliner-cook2ltl", "spacy-sm")
    return span_extractor(Settings()), dependency_parser()
