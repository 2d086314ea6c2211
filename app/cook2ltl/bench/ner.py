"""The span model (GLiNER) against the paper's own method, a spaCy NER, on the same split and the same score.

Both learn from the recipes of brat-dev that are not held out (cook2ltl.parse.training.examples: every fifth recipe is
validation) and are scored with the strict span F1 of cook2ltl.parse.training.evaluate on the held-out sentences. The
spaCy baseline is a blank English pipeline with spaCy's default NER (a CNN tok2vec and a transition-based
parser), trained on the CPU for a fixed number of epochs, seeded, and kept in the model cache so a rerun only
evaluates it.
"""

from __future__ import annotations

import hashlib
import json
import random
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from cook2ltl import paths
from cook2ltl.assembly.backends import SPAN_MODEL
from cook2ltl.assembly.manifest import load_manifest
from cook2ltl.bench.backends import parsers
from cook2ltl.bench.results import write
from cook2ltl.domain.recipe import Label, Span
from cook2ltl.parse.training.brat import read_corpus
from cook2ltl.parse.training.evaluate import Report, strict_f1
from cook2ltl.parse.training.examples import SentenceExample, is_validation, sentence_examples

# The paper's names for the categories.
HEADINGS = {"VERB": "Verb", "WHAT": "What?", "WHERE": "Where?", "HOW": "How?", "TIME": "Time", "TEMP": "Temperature"}


@dataclass(frozen=True)
class SpacyRecipe:
    epochs: int = 30
    dropout: float = 0.2
    seed: int = 13


class SpacySpans:
    """A trained spaCy pipeline as a SpanExtractor: its entities, with our labels, as character spans."""

    def __init__(self, nlp) -> None:
        self.nlp = nlp

    def extract(self, sentences: Sequence[str]) -> list[list[Span]]:
        return [[Span(Label(e.label_), e.start_char, e.end_char, e.text) for e in doc.ents]
                for doc in self.nlp.pipe(sentences)]


def split(data_dir: Path) -> tuple[list[SentenceExample], list[SentenceExample]]:
    """(training, held-out) sentences, the split the span model is trained and scored on."""
    recipes = read_corpus(data_dir)
    training = sentence_examples(r for r in recipes if not is_validation(r.name))
    return training, sentence_examples(r for r in recipes if is_validation(r.name))


def train_spacy(training: list[SentenceExample], recipe: SpacyRecipe, progress: Callable[[str], None]):
    """A blank English NER trained on the sentences; spans spaCy's tokens cannot hold, or that overlap, are left out."""
    # heavy: spaCy (and its training) loads only when the baseline is trained
    import spacy
    from spacy.training import Example
    from spacy.util import filter_spans, fix_random_seed, minibatch

    fix_random_seed(recipe.seed)
    nlp = spacy.blank("en")
    ner = nlp.add_pipe("ner")
    for label in Label:
        ner.add_label(label.value)
    examples, left_out = [], 0
    for sentence in training:
        doc = nlp.make_doc(sentence.text)
        spans = [doc.char_span(s.start, s.end, label=s.label.value) for s in sentence.spans]
        kept = filter_spans([s for s in spans if s is not None])
        left_out += len(sentence.spans) - len(kept)
        examples.append(Example.from_dict(doc, {"entities": [(s.start_char, s.end_char, s.label_) for s in kept]}))
    optimizer = nlp.initialize(lambda: examples)
    shuffler = random.Random(recipe.seed)
    for epoch in range(recipe.epochs):
        shuffler.shuffle(examples)
        losses: dict[str, float] = {}
        for batch in minibatch(examples, size=16):
            nlp.update(batch, drop=recipe.dropout, sgd=optimizer, losses=losses)
        progress(f"spaCy epoch {epoch + 1}/{recipe.epochs}: loss {losses.get('ner', 0.0):.1f}")
    return nlp, left_out


def spacy_baseline(training: list[SentenceExample], recipe: SpacyRecipe, cache: Path | None,
                   progress: Callable[[str], None]) -> tuple[SpacySpans, dict]:
    """The trained baseline from the cache, or trained now (and cached when a cache folder is given)."""
    import spacy  # heavy: loads only when the benchmark runs, not when `bench` lists its choices

    key = hashlib.sha256(json.dumps([spacy.__version__, vars(recipe), [(e.text, [(s.label.value, s.start, s.end)
                                     for s in e.spans]) for e in training]]).encode()).hexdigest()[:12]
    folder = cache / f"spacy-ner-{key}" if cache else None
    if folder is not None and (folder / "bench.json").is_file():
        progress(f"spaCy baseline from {folder}")
        return SpacySpans(spacy.load(folder)), json.loads((folder / "bench.json").read_text())
    started = time.perf_counter()
    nlp, left_out = train_spacy(training, recipe, progress)
    facts = {"train_seconds": round(time.perf_counter() - started, 1), "sentences": len(training),
             "spans_left_out": left_out, "recipe": vars(recipe), "spacy": spacy.__version__}
    if folder is not None:
        partial = folder.with_name(folder.name + ".partial")
        partial.parent.mkdir(parents=True, exist_ok=True)
        nlp.to_disk(partial)
        (partial / "bench.json").write_text(json.dumps(facts, indent=2))
        partial.replace(folder)  # a half-written pipeline never sits under the final name
    return SpacySpans(nlp), facts


def score(extractor, held_out: list[SentenceExample]) -> tuple[Report, float]:
    """Strict span F1 and milliseconds per sentence (after one sentence has loaded the model)."""
    extractor.extract([held_out[0].text])
    started = time.perf_counter()
    predicted = extractor.extract([e.text for e in held_out])
    milliseconds = 1000 * (time.perf_counter() - started) / len(held_out)
    return strict_f1([e.spans for e in held_out], predicted), milliseconds


def report_json(report: Report, milliseconds: float) -> dict:
    rows = {"overall": report.overall, **{label.value: s for label, s in report.per_label.items()}}
    return {"ms_per_sentence": round(milliseconds, 2), "sentences": report.sentences,
            **{name: {"f1": round(s.f1, 4), "precision": round(s.precision, 4), "recall": round(s.recall, 4),
                      "gold": s.gold, "predicted": s.predicted} for name, s in rows.items()}}


def run_ner(smoke: bool, out: Path, echo: Callable[[str], None]) -> dict:
    training, held_out = split(paths.models_dir() / load_manifest()[SPAN_MODEL].data)
    recipe = SpacyRecipe(epochs=1) if smoke else SpacyRecipe()
    if smoke:  # the shape of the work, in seconds: a few sentences each way, nothing cached
        training, held_out = training[:40], held_out[:20]
    baseline, facts = spacy_baseline(training, recipe, None if smoke else paths.model_cache_dir() / "bench", echo)
    scores = {"gliner": score(parsers().spans, held_out), "spacy": score(baseline, held_out)}
    record = {"split": {"training_sentences": len(training), "held_out_sentences": len(held_out)},
              "spacy_training": facts, "models": {name: report_json(*result) for name, result in scores.items()}}
    write(out, "ner", record, ner_markdown(record))
    for name, result in record["models"].items():
        echo(f"{name:<7} strict F1 {result['overall']['f1']:.3f}  {result['ms_per_sentence']:.1f} ms/sentence")
    return record


def ner_markdown(record: dict) -> str:
    names = {"gliner": "GLiNER span model (cook2ltl)", "spacy": "spaCy NER, blank en (paper's method)"}
    labels = ["overall", *(label.value for label in Label)]
    lines = ["| model | " + " | ".join(HEADINGS.get(label, label) for label in labels) + " | ms / sentence |",
             "|---" * (len(labels) + 2) + "|"]
    for name, result in record["models"].items():
        lines.append(f"| {names[name]} | " + " | ".join(f"{result[label]['f1']:.3f}" for label in labels)
                     + f" | {result['ms_per_sentence']:.1f} |")
    split_, facts = record["split"], record["spacy_training"]
    return "\n".join(lines) + (
        f"\n\nStrict span F1 on {split_['held_out_sentences']} held-out sentences; both trained on the same "
        f"{split_['training_sentences']} sentences. spaCy: {facts['recipe']['epochs']} epochs in "
        f"{facts['train_seconds']} s, {facts['spans_left_out']} training spans left out (not on spaCy's token "
        "boundaries, or overlapping).\n")
