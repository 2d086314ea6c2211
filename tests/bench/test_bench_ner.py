"""The spaCy baseline of the NER benchmark: trained on the split's sentences, cached, scored strictly."""

from cook2ltl.bench.ner import SpacyRecipe, SpacySpans, score, spacy_baseline, split
from cook2ltl.domain.recipe import Label, Span
from cook2ltl.parse.training.examples import SentenceExample
from cook2ltl.paths import models_dir

SENTENCES = [SentenceExample("recipe0", text, spans) for text, spans in [
    ("Boil the eggs.", (Span(Label.VERB, 0, 4, "Boil"), Span(Label.WHAT, 5, 13, "the eggs"))),
    ("Chop the onion finely.", (Span(Label.VERB, 0, 4, "Chop"), Span(Label.WHAT, 5, 14, "the onion"),
                                Span(Label.HOW, 15, 21, "finely"))),
    ("Bake for 20 minutes.", (Span(Label.VERB, 0, 4, "Bake"), Span(Label.TIME, 5, 19, "for 20 minutes"))),
    # A span that does not end on one of spaCy's token boundaries cannot be learnt, and is counted.
    ("Stir well.", (Span(Label.VERB, 0, 4, "Stir"), Span(Label.HOW, 5, 7, "we"))),
]]


def test_the_baseline_is_trained_once_then_read_from_the_cache(tmp_path):
    notes = []
    extractor, facts = spacy_baseline(SENTENCES * 5, SpacyRecipe(epochs=12), tmp_path, notes.append)
    assert facts["spans_left_out"] == 5 and facts["sentences"] == 20
    assert notes[-1].startswith("spaCy epoch 12/12")
    report, milliseconds = score(extractor, SENTENCES[:3])
    assert report.overall.f1 > 0.5 and milliseconds > 0  # it has learnt its own training sentences
    assert all(isinstance(s, Span) for spans in extractor.extract(["Boil the eggs."]) for s in spans)
    again, cached_facts = spacy_baseline(SENTENCES * 5, SpacyRecipe(epochs=12), tmp_path, notes.append)
    assert notes[-1].startswith("spaCy baseline from") and cached_facts == facts
    assert isinstance(again, SpacySpans)
    assert [p.name.startswith("spacy-ner-") for p in tmp_path.iterdir()] == [True]


def test_the_split_is_the_span_models():
    training, held_out = split(models_dir() / "training" / "brat-dev")
    assert {e.recipe for e in held_out} == {f"recipe{n}" for n in range(4, 70, 5)}
    assert not {e.recipe for e in training} & {e.recipe for e in held_out}
    assert len(held_out) == 144  # the sentences `cook2ltl models eval-ner` scores
