"""PDDL domains read with unified-planning and kept as `logic` data, cached on disk.

unified-planning parses the file (its reader is the judge of what the file says); its expression trees are
turned into `logic` records, which evaluate a state thousands of times faster than its simulator and need
no import of it on later runs: the records are cached as JSON beside the models, keyed by the file's hash.
"""

from __future__ import annotations

import hashlib
import json
import os
from dataclasses import dataclass
from functools import cache, cached_property
from pathlib import Path

from cook2ltl import files, paths
from cook2ltl.errors import UserError
from cook2ltl.paths import shown
from cook2ltl.world.logic import And, Atom, Condition, Constant, Effect, Equal, Exists, Forall, Not, Or, Schema

CACHE_VERSION = 1
DOMAIN_BYTES = 500_000  # the AI2-THOR domain is 21 kB
CACHE_BYTES = 20_000_000  # its cached records are about 100 kB


@dataclass(frozen=True)
class Domain:
    name: str
    path: Path
    predicates: dict[str, int]  # name → arity
    schemas: dict[str, Schema]

    @cached_property
    def never_added(self) -> frozenset[str]:
        """The predicates no action makes true (what kind of thing each object is, or has stopped being): one
        that does not hold now never will."""
        added = {e.fact.predicate for schema in self.schemas.values() for e in schema.effects if e.value}
        return frozenset(self.predicates) - added


def load_domain(path: Path) -> Domain:
    return _load(Path(os.path.realpath(path)))  # not Path.resolve, which raises on a symlink loop


@cache
def _load(path: Path) -> Domain:
    text = _domain_text(path)
    cached = _cache_file(text)
    try:
        return _from_json(json.loads(files.read_text(cached, CACHE_BYTES, "domain cache", "")), path)
    except (UserError, ValueError, KeyError, TypeError):
        pass  # no cache yet, or a damaged one: read again from the PDDL and rewritten
    domain = _read(path, text)
    try:
        cached.parent.mkdir(parents=True, exist_ok=True)
        partial = cached.with_suffix(".partial")
        partial.write_text(json.dumps(_to_json(domain)), encoding="utf-8")
        partial.replace(cached)
    except OSError:
        pass  # a cache that cannot be written (a read-only disk) only costs the next run a second reading
    return domain


def _domain_text(path: Path) -> str:
    return files.read_text(path, DOMAIN_BYTES, "PDDL domain file",
                           'a primitive set names its PDDL domain with `domain = "file.pddl"`.')


def read_with_unified_planning(path: Path, text: str | None = None):
    """unified-planning's own Problem for the domain file (its text, when already read)."""
    # heavy: unified-planning (~1 s) loads only when a domain is not in the cache yet
    from unified_planning.io import PDDLReader
    from unified_planning.shortcuts import get_environment

    text = _domain_text(path) if text is None else text
    environment = get_environment()
    environment.error_used_name = False  # an object may share a predicate's name (knife, freezer)
    environment.credits_stream = None
    try:
        return PDDLReader(environment).parse_problem_string(text)
    except Exception as error:  # the reader raises many kinds; all mean the file is not a domain we can use
        raise UserError(f"{shown(path)} is not a PDDL domain unified-planning can read: {error}",
                        "see assets/domains/recipe.pddl for the form cook2ltl expects.") from error


def _read(path: Path, text: str) -> Domain:
    problem = read_with_unified_planning(path, text)
    predicates = {fluent.name: fluent.arity for fluent in problem.fluents}
    schemas = {}
    for action in problem.actions:
        parameters = tuple(f"?{p.name}" for p in action.parameters)
        precondition = And(tuple(_condition(c) for c in action.preconditions))
        effects = tuple(_effect(e) for e in action.effects)
        schemas[action.name] = Schema(action.name, parameters, precondition, effects)
    return Domain(problem.name, path, predicates, schemas)


def _term(node) -> str:
    if node.is_parameter_exp():
        return f"?{node.parameter().name}"
    if node.is_variable_exp():
        return f"?{node.variable().name}"
    if node.is_object_exp():
        return node.object().name
    raise UserError(f"unsupported term {node} in a PDDL domain", "arguments must be parameters, variables or objects.")


def _condition(node) -> Condition:
    if node.is_fluent_exp():
        return Atom(node.fluent().name, tuple(_term(a) for a in node.args))
    if node.is_and():
        return And(tuple(_condition(a) for a in node.args))
    if node.is_or():
        return Or(tuple(_condition(a) for a in node.args))
    if node.is_not():
        return Not(_condition(node.arg(0)))
    if node.is_implies():
        return Or((Not(_condition(node.arg(0))), _condition(node.arg(1))))
    if node.is_equals():
        return Equal(_term(node.arg(0)), _term(node.arg(1)))
    if node.is_bool_constant():
        return Constant(node.bool_constant_value())
    if node.is_exists() or node.is_forall():
        variables = tuple(f"?{v.name}" for v in node.variables())
        kind = Exists if node.is_exists() else Forall
        return kind(variables, _condition(node.arg(0)))
    raise UserError(f"unsupported condition {node} in a PDDL domain",
                    "cook2ltl reads STRIPS with negation, or, equality, quantifiers and conditional effects.")


def _effect(effect) -> Effect:
    fact = _condition(effect.fluent)
    if not isinstance(fact, Atom) or not effect.value.is_bool_constant():
        raise UserError(f"unsupported effect {effect} in a PDDL domain", "effects set predicates true or false.")
    condition = _condition(effect.condition) if effect.is_conditional() else Constant(True)
    variables = tuple(f"?{v.name}" for v in effect.forall)
    return Effect(fact, effect.value.bool_constant_value(), condition, variables)


def _cache_file(text: str) -> Path:
    digest = hashlib.sha256(f"{CACHE_VERSION}|{text}".encode()).hexdigest()[:16]
    return paths.model_cache_dir() / "domains" / f"{digest}.json"


# --- JSON: each record as [kind, fields…] -------------------------------------------------------------------


def _to_json(domain: Domain) -> dict:
    return {"name": domain.name, "predicates": domain.predicates,
            "schemas": [[s.name, list(s.parameters), _encode(s.precondition),
                         [[_encode(e.fact), e.value, _encode(e.condition), list(e.variables)] for e in s.effects]]
                        for s in domain.schemas.values()]}


def _from_json(data: dict, path: Path) -> Domain:
    schemas = {}
    for name, parameters, precondition, effects in data["schemas"]:
        schemas[name] = Schema(name, tuple(parameters), _decode(precondition),
                               tuple(Effect(_decode(f), v, _decode(c), tuple(vs)) for f, v, c, vs in effects))
    return Domain(data["name"], path, dict(data["predicates"]), schemas)


def _encode(c: Condition) -> list:
    match c:
        case Atom(predicate, args):
            return ["atom", predicate, list(args)]
        case Equal(left, right):
            return ["eq", left, right]
        case Constant(value):
            return ["const", value]
        case Not(arg):
            return ["not", _encode(arg)]
        case And(args) | Or(args):
            return ["and" if isinstance(c, And) else "or", [_encode(a) for a in args]]
        case Exists(variables, body) | Forall(variables, body):
            return ["exists" if isinstance(c, Exists) else "forall", list(variables), _encode(body)]
    raise TypeError(c)


def _decode(data: list) -> Condition:
    kind = data[0]
    if kind == "atom":
        return Atom(data[1], tuple(data[2]))
    if kind == "eq":
        return Equal(data[1], data[2])
    if kind == "const":
        return Constant(bool(data[1]))
    if kind == "not":
        return Not(_decode(data[1]))
    if kind in ("and", "or"):
        return (And if kind == "and" else Or)(tuple(_decode(a) for a in data[1]))
    if kind in ("exists", "forall"):
        return (Exists if kind == "exists" else Forall)(tuple(data[1]), _decode(data[2]))
    raise ValueError(kind)
