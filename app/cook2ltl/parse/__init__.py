"""Stage 2 of Algorithm 1: semantic parsing of instruction steps into frames."""

from cook2ltl.parse.recipe import parse_recipe

__all__ = ["parse_recipe"]
