"""THOR's interaction rules as a pure state machine.

`apply(state, action)` takes a THOR action dict (``{"action": "PickupObject",
"objectId": ...}``) and returns a `Result`. A refused action returns the very
same state with `success=False` and a message saying why. Geometry is not
modelled: everything not shut inside a closed receptacle counts as visible and
in reach (THOR's `forceAction=True` skips even that check).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import replace
from typing import Any, NamedTuple

from cook2ltl.simulator.agent import AGENT_ACTIONS
from cook2ltl.simulator.state import KitchenState, Refused, Thing, ancestors, contents, enclosing, is_held_or_carried


class Result(NamedTuple):
    state: KitchenState
    success: bool
    error_message: str
    action_return: Any = None
    # THOR's errorCode; the Controller raises ValueError for the argument errors.
    error_code: str = ""


Handler = Callable[[KitchenState, Mapping[str, Any]], tuple[KitchenState, Any]]


def apply(state: KitchenState, action: Mapping[str, Any]) -> Result:
    name = action.get("action")
    handler = HANDLERS.get(name) or AGENT_ACTIONS.get(name)
    if handler is None:
        return Result(state, False, f"Invalid action: {name!r} is not a kitchen action", None, "InvalidAction")
    try:
        new_state, returned = handler(state, action)
    except Refused as refusal:
        return Result(state, False, refusal.message, None, refusal.code)
    return Result(settle(new_state), True, "", returned)


def settle(state: KitchenState) -> KitchenState:
    """Let heat, cold and water act: what sits in a running heat source gets Hot
    (and cooked, if cookable; a running coffee machine fills its cup), what sits
    in a cold source gets Cold, what sits in a sink basin under a running faucet
    is rinsed clean and, if it holds liquid, filled with water. Things keep their
    temperature once taken out."""
    hot = {oid for oid, t in state.objects.items() if t.can("isHeatSource") and t.is_toggled}
    cold = {oid for oid, t in state.objects.items() if t.can("isColdSource")}
    wet = _under_running_water(state)
    changed = []
    for thing in state.objects.values():
        outer = list(ancestors(state, thing.object_id))
        heaters = [o for o in outer if o.object_id in hot]
        updated = thing
        if heaters:
            updated = replace(thing, temperature="Hot", is_cooked=thing.is_cooked or thing.can("cookable"))
            brews = any(h.object_type == "CoffeeMachine" for h in heaters)
            if brews and _fillable(thing):
                updated = replace(updated, is_filled=True, fill_liquid="coffee")
        elif any(o.object_id in cold for o in outer):
            updated = replace(thing, temperature="Cold")
        if any(o.object_id in wet for o in outer):
            updated = replace(updated, is_dirty=False)
            if _fillable(updated):
                updated = replace(updated, is_filled=True, fill_liquid="water")
        if updated != thing:
            changed.append(updated)
    return state.evolve(objects=state.with_things(*changed)) if changed else state


def _fillable(thing: Thing) -> bool:
    return thing.can("canFillWithLiquid") and not thing.is_filled and not thing.is_broken


def _under_running_water(state: KitchenState) -> set[str]:
    """The sink basins whose faucet runs. The scenes do not link the two, so a
    basin's faucet is the nearest one."""
    faucets = [t for t in state.objects.values() if t.object_type == "Faucet"]
    running = set()
    for basin in state.objects.values():
        if basin.object_type == "SinkBasin" and faucets:
            nearest = min(faucets, key=lambda f: math.dist(f.position, basin.position))
            if nearest.is_toggled:
                running.add(basin.object_id)
    return running


# --- argument and precondition helpers -------------------------------------


def target(state: KitchenState, action: Mapping[str, Any]) -> Thing:
    object_id = action.get("objectId")
    if not object_id:
        raise Refused(f"{action['action']} needs an objectId", "MissingArguments")
    thing = state.thing(object_id)
    if thing is None:
        raise Refused(f"No object with objectId {object_id!r} in {state.scene}")
    return thing


def need(condition: bool, message: str) -> None:
    if not condition:
        raise Refused(message)


def reachable(state: KitchenState, thing: Thing, action: Mapping[str, Any]) -> None:
    if action.get("forceAction"):
        return
    shut_in = enclosing(state, thing.object_id)
    need(shut_in is None, f"{thing.object_id} is inside the closed {shut_in and shut_in.object_id}; open it first")


def _moved(state: KitchenState, root: Thing, parent: str | None, position) -> list[Thing]:
    """`root` now in `parent` at `position`; what it carries moves along."""
    riders = [replace(state.objects[oid], position=position) for oid in contents(state, root.object_id)]
    return [replace(root, parent=parent, position=position), *riders]


# --- holding ----------------------------------------------------------------


def pickup(state, action):
    thing = target(state, action)
    need(state.held is None, f"The agent already holds {state.held}; it can hold one object at a time")
    need(thing.can("pickupable"), f"{thing.object_id} is not pickupable")
    need(not thing.is_broken, f"{thing.object_id} is broken and cannot be picked up")
    reachable(state, thing, action)
    # In hand, the object has no container; what it carries stays inside it.
    objects = state.with_things(replace(thing, parent=None))
    return state.evolve(objects=objects, held=thing.object_id), None


def put(state, action):
    receptacle = target(state, action)
    need(state.held is not None, "The agent holds nothing to put down")
    held = state.objects[state.held]
    need(
        not is_held_or_carried(state, receptacle.object_id),
        f"Cannot put {held.object_id} into itself or into something it carries",
    )
    need(receptacle.can("receptacle"), f"{receptacle.object_id} is not a receptacle")
    need(
        not receptacle.can("openable") or receptacle.is_open,
        f"{receptacle.object_id} is closed; open it before putting things in",
    )
    reachable(state, receptacle, action)
    need(
        state.types.fits(held.object_type, receptacle.object_type),
        f"A {held.object_type} cannot be put in or on a {receptacle.object_type}",
    )
    objects = state.with_things(*_moved(state, held, receptacle.object_id, receptacle.position))
    return state.evolve(objects=objects, held=None), None


def drop(state, action):
    need(state.held is not None, "The agent holds nothing to drop")
    held = state.objects[state.held]
    floor = next((t.object_id for t in state.objects.values() if t.object_type == "Floor"), None)
    x, _, z = state.agent.position
    objects = state.with_things(*_moved(state, held, floor, (x, 0.0, z)))
    return state.evolve(objects=objects, held=None), None


# --- opening and switching ------------------------------------------------------


def open_object(state, action):
    thing = target(state, action)
    openness = action.get("openness", 1.0)
    if not isinstance(openness, (int, float)) or not 0.0 < openness <= 1.0:
        raise Refused(f"openness must be in (0, 1], got {openness!r}", "InvalidArgument")
    need(thing.can("openable"), f"{thing.object_id} cannot be opened")
    need(not thing.is_open, f"{thing.object_id} is already open")
    reachable(state, thing, action)
    need(
        not (thing.can("toggleable") and thing.is_toggled),
        f"{thing.object_id} is on; turn it off before opening it",
    )
    return _changed(state, replace(thing, is_open=True, openness=float(openness))), None


def close_object(state, action):
    thing = target(state, action)
    need(thing.can("openable"), f"{thing.object_id} cannot be closed")
    need(thing.is_open, f"{thing.object_id} is already closed")
    reachable(state, thing, action)
    return _changed(state, replace(thing, is_open=False, openness=0.0)), None


def toggle_on(state, action):
    return _toggle(state, action, on=True)


def toggle_off(state, action):
    return _toggle(state, action, on=False)


def _toggle(state, action, on: bool):
    thing = target(state, action)
    if not thing.can("toggleable"):
        knobs = [t.object_id for t in state.objects.values() if thing.object_id in (t.controlled or ())]
        hint = f"; it is switched by {', '.join(knobs)}" if knobs else ""
        raise Refused(f"{thing.object_id} cannot be switched on or off{hint}")
    need(thing.is_toggled != on, f"{thing.object_id} is already {'on' if on else 'off'}")
    reachable(state, thing, action)
    need(not thing.is_broken, f"{thing.object_id} is broken")
    if on:
        need(
            not (thing.can("openable") and thing.is_open),
            f"{thing.object_id} is open; close it before turning it on",
        )
    # A stove knob switches its burners, which are the heat sources.
    switched = [replace(state.objects[oid], is_toggled=on) for oid in thing.controlled or () if oid in state.objects]
    return state.evolve(objects=state.with_things(replace(thing, is_toggled=on), *switched)), None


# --- changing objects -----------------------------------------------------------


def slice_object(state, action):
    thing = target(state, action)
    need(thing.can("sliceable"), f"{thing.object_id} cannot be sliced")
    _put_down_first(state, thing, "slicing")
    reachable(state, thing, action)
    if state.slice_needs_knife:
        tools = " or ".join(sorted(state.types.cutting_tools))
        held = state.held and state.objects[state.held].object_type
        need(
            held in state.types.cutting_tools,
            f"Slicing needs a {tools} in hand; the agent holds {held or 'nothing'}",
        )
    return _split(state, thing)


def break_object(state, action):
    thing = target(state, action)
    need(thing.can("breakable"), f"{thing.object_id} cannot be broken")
    need(not thing.is_broken, f"{thing.object_id} is already broken")
    reachable(state, thing, action)
    if thing.object_type in state.types.slicing:
        # An egg breaks into a cracked egg, as when cut: so, as for cutting, not in the hand.
        _put_down_first(state, thing, "breaking")
        return _split(state, thing)
    broken = replace(thing, is_broken=True, is_filled=False, fill_liquid=None)
    return _changed(state, broken), None


def _put_down_first(state, thing: Thing, doing: str) -> None:
    """Splitting (cutting, cracking an egg) happens where the thing lies: not in the hand, nor in what the
    hand holds. It also keeps `held` naming an object, as splitting removes the thing."""
    need(not is_held_or_carried(state, thing.object_id), f"Put {thing.object_id} down before {doing} it")


def _split(state, thing: Thing):
    """Replace `thing` by its pieces, in its place; the pieces' ids are returned."""
    rule = state.types.slicing.get(thing.object_type)
    need(rule is not None, f"No slicing rule for {thing.object_type} in assets/kitchens/rules.toml")
    abilities = frozenset({"pickupable", "cookable"} if rule.cookable else {"pickupable"})
    pieces = [
        Thing(
            object_id=f"{thing.object_id}|{rule.into}_{n}",
            object_type=rule.into,
            name=f"{thing.name}_{rule.into}_{n}",
            position=thing.position,
            abilities=abilities,
            parent=thing.parent,
            is_cooked=thing.is_cooked and rule.cookable,
            temperature=thing.temperature,
        )
        for n in range(rule.pieces)
    ]
    objects = state.with_things(*pieces, removed=(thing.object_id,))
    return state.evolve(objects=objects), [p.object_id for p in pieces]


def cook(state, action):
    thing = target(state, action)
    need(thing.can("cookable"), f"{thing.object_id} cannot be cooked")
    need(not thing.is_cooked, f"{thing.object_id} is already cooked")
    reachable(state, thing, action)
    return _changed(state, replace(thing, is_cooked=True)), None


def fill(state, action):
    thing = target(state, action)
    liquid = action.get("fillLiquid")
    if not liquid:
        raise Refused("FillObjectWithLiquid needs a fillLiquid", "MissingArguments")
    if liquid not in state.types.liquids:
        known = ", ".join(sorted(state.types.liquids))
        raise Refused(f"fillLiquid must be one of {known}, got {liquid!r}", "InvalidArgument")
    need(thing.can("canFillWithLiquid"), f"{thing.object_id} cannot hold liquid")
    need(not thing.is_broken, f"{thing.object_id} is broken")
    need(not thing.is_filled, f"{thing.object_id} is already filled with {thing.fill_liquid}")
    reachable(state, thing, action)
    return _changed(state, replace(thing, is_filled=True, fill_liquid=liquid)), None


def empty(state, action):
    thing = target(state, action)
    need(thing.can("canFillWithLiquid"), f"{thing.object_id} cannot hold liquid")
    need(thing.is_filled, f"{thing.object_id} is already empty")
    reachable(state, thing, action)
    return _changed(state, replace(thing, is_filled=False, fill_liquid=None)), None


def use_up(state, action):
    thing = target(state, action)
    need(thing.can("canBeUsedUp"), f"{thing.object_id} cannot be used up")
    need(not thing.is_used_up, f"{thing.object_id} is already used up")
    reachable(state, thing, action)
    return _changed(state, replace(thing, is_used_up=True)), None


def dirty(state, action):
    return _soil(state, action, dirty=True)


def clean(state, action):
    return _soil(state, action, dirty=False)


def _soil(state, action, dirty: bool):
    thing = target(state, action)
    need(thing.can("dirtyable"), f"{thing.object_id} cannot get dirty or be cleaned")
    need(thing.is_dirty != dirty, f"{thing.object_id} is already {'dirty' if dirty else 'clean'}")
    reachable(state, thing, action)
    return _changed(state, replace(thing, is_dirty=dirty)), None


def _changed(state: KitchenState, thing: Thing) -> KitchenState:
    return state.evolve(objects=state.with_things(thing))


HANDLERS: dict[str, Handler] = {
    "PickupObject": pickup,
    "PutObject": put,
    "DropHandObject": drop,
    "OpenObject": open_object,
    "CloseObject": close_object,
    "ToggleObjectOn": toggle_on,
    "ToggleObjectOff": toggle_off,
    "SliceObject": slice_object,
    "BreakObject": break_object,
    "CookObject": cook,
    "FillObjectWithLiquid": fill,
    "EmptyLiquidFromObject": empty,
    "UseUpObject": use_up,
    "DirtyObject": dirty,
    "CleanObject": clean,
}
