"""cook2ltl: cooking recipes to Linear Temporal Logic task specifications, offline."""

__version__ = "0.1.0"
