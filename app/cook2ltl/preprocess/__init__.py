"""Stage 1 of Algorithm 1: split a recipe into instruction steps."""

from cook2ltl.preprocess.clean import visible_text
from cook2ltl.preprocess.sentences import split_sentences

__all__ = ["split_sentences", "visible_text"]
