"""Stage 4 of Algorithm 1: the action library 𝔸, cached reductions reused across recipes and runs."""

from cook2ltl.library.store import SCHEMA_VERSION, Library, LibraryEntry, Review, Status, Version, reviewer

__all__ = ["SCHEMA_VERSION", "Library", "LibraryEntry", "Review", "Status", "Version", "reviewer"]
