"""Checks a library body as the pipeline would use it, line by line: for `library edit` and the app's editor.

An adapter over the core's own readers (`read_call`, `bind`, `instantiate`, `expand`): a body passes when
every line is a call of a primitive or a live library verb with the right number of arguments, its `$`
placeholders are the action's parameters, and it expands down to primitives.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from cook2ltl.domain.actions import PrimitiveSet
from cook2ltl.reduce.body import bind, instantiate, read_call
from cook2ltl.reduce.reduction import MAX_PLAN, LibraryVerb, expand


def verb_finder(verbs: Sequence[LibraryVerb], verb: str,
                signature: tuple[str, ...]) -> Callable[[str, int], LibraryVerb | None]:
    """Look-ups of the library verbs a body of verb(signature) may call: all but the entry itself (a cycle)."""
    others = [v for v in verbs if not (v.verb == verb and v.signature == signature)]

    def find(name: str, arity: int) -> LibraryVerb | None:
        return next((v for v in others if v.verb == name and len(v.signature) == arity), None)

    return find


def body_problems(body: str, verb: str, signature: tuple[str, ...], primitives: PrimitiveSet,
                  verbs: Sequence[LibraryVerb]) -> list[str]:
    """What stops the pipeline from using `body` for verb(signature); empty when it would use it."""
    find = verb_finder(verbs, verb, signature)
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
        problems += [f"line {number}: {p}" for p in _call_problems(call, primitives, find, allowed)]
    if not lines:
        return ["the body has no lines"]
    if problems:
        return problems
    calls = instantiate(body, allowed)
    if calls is None or expand(calls, primitives, find) is None:
        return ["the body does not expand to primitives (library verbs calling each other in a cycle, "
                f"or a plan of more than {MAX_PLAN} calls)"]
    return []


def _call_problems(call, primitives: PrimitiveSet, find: Callable[[str, int], LibraryVerb | None],
                   allowed: dict[str, str]) -> list[str]:
    problems = []
    primitive = primitives.get(call.name)
    if primitive is not None:
        arity = 2 if call.is_wait else primitive.object_arity
        if len(call.args) != arity:
            problems.append(f"{call.name} takes {arity} argument{'s' if arity != 1 else ''}, not {len(call.args)}")
    elif find(call.name, len(call.args)) is None:
        problems.append(f"{call.name} with {len(call.args)} argument(s) is neither a primitive of {primitives.name} "
                        "nor a live library verb")
    unknown = [arg for arg in call.args if arg.startswith("$") and arg not in allowed]
    if unknown:
        known = ", ".join(allowed) or "none"
        parameters = "is not a parameter" if len(unknown) == 1 else "are not parameters"
        problems.append(f"{', '.join(unknown)} {parameters} of this action (it has {known})")
    return problems
