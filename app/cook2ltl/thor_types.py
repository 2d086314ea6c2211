"""AI2-THOR's object types: what fits where, what slices into what, which are liquids and cutting tools.

THOR's own vocabulary, the same in a real build and in the embedded kitchen, read from
assets/kitchens/rules.toml; the simulator, the world model and the robot's executor all speak it."""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache

from cook2ltl.paths import assets_dir


@dataclass(frozen=True)
class SliceRule:
    into: str
    pieces: int
    cookable: bool


@dataclass(frozen=True)
class TypeRules:
    """Per-object-type facts: what fits where, what slices into what."""

    receptacles: Mapping[str, frozenset[str]]
    slicing: Mapping[str, SliceRule]
    cutting_tools: frozenset[str]
    liquids: frozenset[str]

    def fits(self, object_type: str, receptacle_type: str) -> bool:
        return receptacle_type in self.receptacles.get(object_type, frozenset())


@lru_cache(maxsize=1)
def load_type_rules() -> TypeRules:
    with open(assets_dir() / "kitchens" / "rules.toml", "rb") as f:
        raw = tomllib.load(f)
    return TypeRules(
        receptacles={obj: frozenset(recs) for obj, recs in raw["receptacles"].items()},
        slicing={
            obj: SliceRule(into=r["into"], pieces=int(r["pieces"]), cookable=bool(r["cookable"]))
            for obj, r in raw["slicing"].items()
        },
        cutting_tools=frozenset(raw["cutting_tools"]),
        liquids=frozenset(raw["liquids"]),
    )


def liquids() -> frozenset[str]:
    return load_type_rules().liquids
