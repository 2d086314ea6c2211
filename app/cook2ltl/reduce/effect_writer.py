"""The intended effect of a verb the verb-effect table lacks, written by the model under a grammar.

The prompt shows the table's own entries as examples, one verb for each state the table uses:

    def refrigerate(food: what):
        cold(food)
        in(food, fridge)

and then the action's header. The model writes one atom among those the world can observe, over the
action's objects and the kitchen places the table names (fridge, plate …), or a blank line: a verb with no
observable effect ("serve") gets none. The atom is stored with the action's values put back as slots
(`boiled(what)`), like the table's.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from cook2ltl.domain.actions import Action, Usage
from cook2ltl.reduce.llm import LanguageModel
from cook2ltl.reduce.prompt import header
from cook2ltl.world.effects import SLOTS, Template, parse_template, template_text
from cook2ltl.world.logic import State
from cook2ltl.world.world import World

# One atom, the model's best guess: effects are minimal and certain, and asked for more, a 1.5B model always
# goes on with ones that contradict or have nothing to do with the verb (sizzle → sliced, toss → in(bin, apple)).
MAX_ATOMS = 1
TOKENS_PER_ATOM = 16
EXAMPLE_VALUES = {"what": "food", "where": "pot", "how": "oil"}  # the examples' objects, by slot
HEADER = "# The states each cooking action leaves, one per line; a verb that leaves none has no lines.\n"


def effect_prompt(table: Mapping[str, Sequence[Template]]) -> str:
    """The examples: for each predicate of the table, its plainest single-object entry (fewest atoms, then
    one word, then first in the table, which lists the commonest verb of a kind first), so the model sees
    every state once; and the plainest verb that leaves none."""
    order = {verb: index for index, verb in enumerate(table)}

    def plainest(verbs: list[str]) -> str:
        return min(verbs, key=lambda v: (len(table[v]), v.count("_"), order[v]))

    single_object = {"what"} | _constants(table)
    shown: dict[str, Sequence[Template]] = {}
    for predicate in sorted({p for templates in table.values() for p, _ in templates}):
        fitting = [v for v, ts in table.items() if any(p == predicate for p, _ in ts)
                   and all(set(args) <= single_object for _, args in ts)]
        if fitting:
            shown[plainest(fitting)] = table[plainest(fitting)]
    if none := [v for v, ts in table.items() if not ts]:
        shown[plainest(none)] = ()
    blocks = [f"def {verb}({EXAMPLE_VALUES['what']}: what):\n"
              + "".join(f"    {template_text(_example(t))}\n" for t in templates)
              for verb, templates in shown.items()]
    return HEADER + "\n".join(blocks) + "\n"


def write_effect(action: Action, model: LanguageModel, world: World, state: State,
                 table: Mapping[str, Sequence[Template]]) -> tuple[tuple[Template, ...], Usage]:
    """The model's effect for `action`, as templates over its slots, and what writing it cost."""
    options = _atoms(action, world, state, table)

    def next_lines(text: str) -> list[str] | None:
        written = [line for line in text.splitlines() if line.strip()]
        return options if len(written) < MAX_ATOMS else None

    completion = model.complete_lines(effect_prompt(table), header(action), next_lines, TOKENS_PER_ATOM)
    slots = {p.value: p.category for p in action.parameters if p.category in SLOTS}
    templates = []
    for line in completion.text.splitlines():
        if line.strip() in options:
            predicate, args = parse_template(line.strip())
            templates.append((predicate, tuple(slots.get(arg, arg) for arg in args)))
    return tuple(dict.fromkeys(templates)), completion.usage


def _atoms(action: Action, world: World, state: State, table: Mapping[str, Sequence[Template]]) -> list[str]:
    """Every atom the model may write: a table predicate the world observes, over the action's objects. The
    place something ends in is one of them that is no liquid, or, for an action that names no place, a
    kitchen place the table names (the fridge for "chill")."""
    objects = [p.value for p in action.parameters if p.category in SLOTS and p.value in state.objects]
    named_place = any(p.category == "where" for p in action.parameters)
    places = [o for o in objects if ("liquid", o) not in state.facts]
    places += [] if named_place else sorted(c for c in _constants(table) if c in state.objects)
    atoms = []
    for predicate in sorted({p for templates in table.values() for p, args in templates}):
        arity = world.domain.predicates.get(world.predicate(predicate) or predicate)
        if arity == 1 and world.predicate(predicate):
            atoms += [f"{predicate}({x})" for x in objects]
        elif arity == 2:
            atoms += [f"{predicate}({x}, {y})" for x in objects for y in places if x != y]
    return list(dict.fromkeys(atoms))


def _constants(table: Mapping[str, Sequence[Template]]) -> set[str]:
    return {arg for templates in table.values() for _, args in templates for arg in args if arg not in SLOTS}


def _example(template: Template) -> Template:
    predicate, args = template
    return predicate, tuple(EXAMPLE_VALUES.get(arg, arg) for arg in args)
