"""Checks a library body as the pipeline would use it, line by line: for `library edit` and the app's editor.

An adapter over the core's own readers (`read_call`, `bind`, `instantiate`, `expand`): a body passes when
every line is a call of a primitive or a live library verb with the right number of arguments, its `$`
placeholders are the action's parameters, and it expands down to primitives.
"""

from __future__ import annotations

from collections.abc import Sequence

from cook2ltl.reduce.body import bind, instantiate, read_call
from cook2ltl.reduce.model import PrimitiveSet
from cook2ltl.reduce.reduction import LibraryVerb, expand


def body_problems(body: str, verb: str, signature: tuple[str, ...], primitives: PrimitiveSet,
                  verbs: Sequence[LibraryVerb]) -> list[str]:
    """What stops the pipeline from using `body` for verb(signature); empty when it would use it."""
    others = [v for v in verbs if not (v.verb == verb and v.signature == signature)]  # the entry itself: a cycle
    allowed = bind(signature, signature)  # {"$what": "what", …}
    problems, lines = [], 0
    for number, raw in enumerate(body.splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        lines += 1
        call = read_call(line)
        if call is None:
            problems.append(f"line {number}: “{line}” is not a call such as put($what, pot)")
            continue
        problems += [f"line {number}: {p}" for p in _call_problems(call, primitives, others, allowed)]
    if not lines:
        return ["the body has no lines"]
    if problems:
        return problems
    def find(name: str, arity: int) -> LibraryVerb | None:
        return next((v for v in others if v.verb == name and len(v.signature) == arity), None)

    calls = instantiate(body, allowed)
    if calls is None or expand(calls, primitives, find) is None:
        return ["the body does not expand to primitives (library verbs calling each other in a cycle, "
                "or a plan of more than 60 calls)"]
    return []


def _call_problems(call, primitives: PrimitiveSet, verbs: Sequence[LibraryVerb], allowed: dict[str, str]) -> list[str]:
    problems = []
    primitive = primitives.get(call.name)
    if primitive is not None:
        arity = 2 if call.is_wait else primitive.object_arity
        if len(call.args) != arity:
            problems.append(f"{call.name} takes {arity} argument{'s' if arity != 1 else ''}, not {len(call.args)}")
    elif not any(v.verb == call.name and len(v.signature) == len(call.args) for v in verbs):
        problems.append(f"{call.name} with {len(call.args)} argument(s) is neither a primitive of {primitives.name} "
                        "nor a live library verb")
    unknown = [arg for arg in call.args if arg.startswith("$") and arg not in allowed]
    if unknown:
        known = ", ".join(allowed) or "none"
        parameters = "is not a parameter" if len(unknown) == 1 else "are not parameters"
        problems.append(f"{', '.join(unknown)} {parameters} of this action (it has {known})")
    return problems
