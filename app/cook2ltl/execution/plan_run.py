"""One plan run line by line in a kitchen that was just reset: what `KitchenValidator` reports.

Lines the ai2thor executor knows go through it (it teleports to the object and sends THOR's action);
the others are checked here with the same metadata. Error messages name the plan's objects, not THOR's
objectIds, so they can go back to the model as they are.
"""

from __future__ import annotations

import re

from cook2ltl.domain.actions import TIMER, WAIT, Action, Call, Primitive, PrimitiveSet
from cook2ltl.execution.executor import Kitchen, execute, send, thor_primitives
from cook2ltl.ltl.ast import Atom
from cook2ltl.reduce.validation import LineProblem
from cook2ltl.thor_types import liquids
from cook2ltl.world.stand_ins import Casting, plan_names
from cook2ltl.world.thor_facts import PREDICATES
from cook2ltl.world.thor_names import Binding, UnknownObject, held, objects_named, resolve, shut_away, snake_case

# Cooking verbs and the state they leave their object in, as the kitchen reports it.
VERB_GOALS = {
    **dict.fromkeys(("chop", "slice", "cut", "dice", "mince", "cube", "halve", "quarter"), ("sliced",)),
    **dict.fromkeys(("heat", "warm", "microwave", "boil", "simmer", "fry", "saute", "bake", "roast", "toast",
                     "grill", "cook", "brown", "melt"), ("hot",)),
    **dict.fromkeys(("chill", "refrigerate", "cool", "freeze"), ("cold",)),
}
_OBJECT_ID = re.compile(r"\b([A-Z][A-Za-z]*)\|[+-]?[0-9.]+\|[+-]?[0-9.]+\|[+-]?[0-9.]+(?:\|[A-Za-z_0-9]+)*")

MAX_WAITS = 3
# What a line can mean besides an AI2-THOR primitive (a set's [thor] table names them): the object must be
# within reach; fill with a liquid, or have the poured thing in hand.
TOUCH, POUR = "touch", "pour"


def meanings(primitives: PrimitiveSet) -> dict[str, Primitive | str]:
    """What each primitive of the set does in the kitchen: the AI2-THOR primitive it runs as, or TOUCH or POUR.
    A primitive with no meaning the kitchen can run is left out."""
    thor, declared = thor_primitives(), dict(primitives.in_thor)
    found: dict[str, Primitive | str] = {}
    for primitive in primitives.primitives:
        meaning = declared.get(primitive.name, primitive.name)
        if meaning in (TOUCH, POUR) or thor.get(meaning) is not None:
            found[primitive.name] = thor.get(meaning) or meaning
    return found


class PlanRun:
    def __init__(self, kitchen: Kitchen, frame: Casting, meaning: dict[str, Primitive | str]) -> None:
        self.kitchen = kitchen
        self.meaning = meaning
        self.binding = Binding(frame.bound)
        self.scene = frame.scene

    def run(self, action: Action, plan: tuple[Call, ...], before: tuple[Call, ...] | None = None
            ) -> tuple[LineProblem, ...]:
        """The plan's problems, line by line. `before`: the recipe's earlier lines, run first (what they could
        not do is not this plan's problem); without them the plan's shut-away things are set out first."""
        if before is None:
            self._set_out(plan_names(plan))
        for call in before or ():
            self._attempt(call)
        problems = []
        for line, call in enumerate(plan, 1):
            error = self._attempt(call)
            if error:
                problems.append(LineProblem(line, call.text(), self._named(error)))
        problems.extend(self._goal(action))
        return tuple(problems)

    def _attempt(self, call: Call) -> str:
        try:
            return self._line(call)
        except UnknownObject as missing:
            return missing.message

    def _set_out(self, names: tuple[str, ...]) -> None:
        """Mise en place, as the paper assumes: a thing the plan names that is shut away (the egg in the fridge)
        is first set out on a counter, so the check is about the plan's steps, not the kitchen's cupboards.
        Containers and appliances stay as they are: a closed fridge must still be opened."""
        counter = next((o["objectId"] for o in self._objects() if o["objectType"] == "CounterTop"), None)
        for name in names:
            candidates = [o for o in objects_named(name, self._objects(), self.binding) if o.get("pickupable")]
            shut = shut_away(self._objects())
            if counter is None or not candidates or any(o["objectId"] not in shut for o in candidates):
                continue
            thing = candidates[0]["objectId"]
            for step in ({"action": "PickupObject", "objectId": thing}, {"action": "PutObject", "objectId": counter}):
                send(self.kitchen, {**step, "forceAction": True})

    def _line(self, call: Call) -> str:
        meaning = self.meaning[call.name]
        args = call.args
        if meaning == TOUCH:
            return self._reach(args[0])
        name = meaning if meaning == POUR else meaning.name
        if name == WAIT:
            return self._wait(*args)
        if name == POUR or (name == "put" and args[0] in liquids()):
            return self._fill(args[1], args[0]) if args[0] in liquids() else self._pour(*args)
        if name == "fill":
            return self._fill(*args)
        atom = Atom(name, args[:meaning.object_arity])  # remove(what, where) runs as pick_up(what)
        attempt, self.binding = execute(self.kitchen, atom, self.binding)
        return "" if attempt.success else attempt.error.removeprefix(f"{atom.text}: ")

    def _fill(self, container: str, liquid: str) -> str:
        atom = Atom("fill", (container, liquid))
        attempt, self.binding = execute(self.kitchen, atom, self.binding)
        if attempt.success:  # from now on the liquid is where it was poured: wait(water == hot) asks the pot
            self.binding = self.binding.bind(liquid, self.binding.objects[container])
        return "" if attempt.success else attempt.error.removeprefix(f"{atom.text}: ")

    def _pour(self, what: str, where: str) -> str:
        """Pouring a thing (the pot's contents, the batter) needs it in hand and the target open."""
        objects = self._objects()
        holding = held(objects)
        if holding is None or holding not in objects_named(what, objects, self.binding):
            return f"not holding {what}; pick it up before pouring it"
        return self._reach(where)

    def _reach(self, name: str) -> str:
        target, self.binding = resolve(name, self._objects(), self.binding, scene=self.scene)
        return f"{name} is shut in a closed receptacle; open it first" if target in shut_away(self._objects()) else ""

    def _wait(self, subject: str, state: str) -> str:
        if subject == TIMER or state not in PREDICATES:
            send(self.kitchen, {"action": "Pass"})
            return ""  # a timer, or a state the kitchen cannot observe: nothing to check
        for _ in range(MAX_WAITS):
            if self._holds(subject, state):
                return ""
            send(self.kitchen, {"action": "Pass"})
        return "" if self._holds(subject, state) else f"goal state not reached: {subject} never became {state}"

    def _goal(self, action: Action) -> list[LineProblem]:
        """The state an action names (`until cold`) or its verb implies (chop: sliced) for its first object,
        if the kitchen can observe it."""
        whats = [p.value for p in action.parameters if p.category == "what"]
        states = list(dict.fromkeys([*(v for v in action.values if v in PREDICATES), *VERB_GOALS.get(action.verb, ())]))
        if not whats or not states or not self._named_anything(whats[0]):
            return []
        return [LineProblem(0, action.text(), f"goal state not reached: {whats[0]} is not {state} at the end")
                for state in states if not self._holds(whats[0], state)]

    def _holds(self, name: str, state: str) -> bool:
        return any(PREDICATES[state](o) for o in objects_named(name, self._objects(), self.binding))

    def _named_anything(self, name: str) -> bool:
        return bool(objects_named(name, self._objects(), self.binding))

    def _objects(self):
        return self.kitchen.last_event.metadata["objects"]

    def _named(self, message: str) -> str:
        """THOR's objectIds in a message replaced by the names the plan bound them to."""
        names = [(n, i) for n, i in self.binding.objects.items() if n not in liquids()]  # water names its pot
        for name, object_id in sorted(names, key=lambda item: -len(item[1])):
            message = message.replace(object_id, name)
        return _OBJECT_ID.sub(lambda match: snake_case(match[1]), message)
