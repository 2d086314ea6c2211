"""The task suite in assets/tasks/: the paper's four, the rest and the held-out paraphrases, each goal unmet at
the start and reached by its reference plan through ai2thor's Controller; goal conditions on THOR metadata; the
files' checks."""

import pytest

from cook2ltl.assembly.trial import TrialDone, reference_formula, run_trial
from cook2ltl.errors import UserError
from cook2ltl.execution.rollout import Stop
from cook2ltl.execution.tasks import (
    CATEGORIES,
    PARAPHRASES,
    GoalCondition,
    check_goal,
    condition_met,
    find_task,
    load_tasks,
    paraphrases_file,
    tasks_file,
)
from cook2ltl.ltl import Verdict, parse

PAPER = {"microwave-potato": "Microwave the potato.", "chop-tomato": "Chop the tomato.",
         "cut-bread": "Cut the bread.", "refrigerate-apple": "Refrigerate the apple."}


def test_the_papers_four_tasks_and_at_least_twenty_more_across_the_kitchens():
    tasks = load_tasks()
    assert {t.id: t.instruction for t in tasks if t.source.startswith("paper")} == PAPER
    assert len(tasks) - len(PAPER) >= 20
    assert {t.category for t in tasks} == set(CATEGORIES)
    assert len({t.scene for t in tasks}) >= 25
    assert all(t.reference for t in tasks)


# paraphrases.toml's instructions, fixed before any measurement: never reworded to make a task pass.
PARAPHRASED = [
    "Heat the potato up in the microwave.", "Put the apple in the fridge to chill it.",
    "Cut the bread into slices and toast them.", "Chop the apple, then refrigerate it.", "Switch the microwave on.",
    "Get some water into the mug.", "Place the egg in the bowl and microwave it.",
    "Take the lettuce and cool it in the refrigerator.", "Dice the potato and fry it in the pan.",
    "Turn the faucet on.", "Warm up the mug in the microwave, then switch the microwave off.",
    "Wash the dirty plate in the sink.", "Slice the tomato and put it on the plate.",
    "Pour coffee into the mug using the coffee machine.", "Boil some water in the pot on the stove.",
]


def test_the_paraphrases_follow_the_33_tasks_with_their_wordings_unchanged():
    tasks, paraphrases = load_tasks(tasks_file()), load_tasks(paraphrases_file())
    assert len(tasks) == 33 and load_tasks() == tasks + paraphrases  # so every test here covers both files
    assert [t.instruction for t in paraphrases] == PARAPHRASED
    assert {t.source for t in paraphrases} == {PARAPHRASES} and PARAPHRASES not in {t.source for t in tasks}
    assert find_task("Turn the faucet on.").id == "para-faucet-on"


def test_a_task_is_found_by_id_or_instruction():
    assert find_task("microwave-potato").id == "microwave-potato"
    assert find_task("microwave the potato").id == "microwave-potato"
    assert find_task("  Microwave the  Potato. ").id == "microwave-potato"
    assert find_task("F(pick_up(apple))") is None


def trial(kitchen, task):
    events = list(run_trial(kitchen, reference_formula(task), task.scene, task))
    assert isinstance(events[-1], TrialDone)
    return events[-1].trial


def test_every_reference_plan_reaches_its_goal_which_the_kitchen_does_not_start_with(kitchen):
    for task in load_tasks():
        kitchen.reset(task.scene)
        for step in task.setup:  # the same setup run_trial does, to look at the start
            kitchen.step(action=step["action"], forceAction=True,
                         objectId=next(o["objectId"] for o in kitchen.last_event.metadata["objects"]
                                       if o["objectType"] == step["object"]))
        assert not check_goal(task, kitchen.last_event.metadata["objects"]).met, task.id
        done = trial(kitchen, task)
        assert done.success and done.goal.met, (task.id, [a.error for a in done.rollout.failures])
        assert done.rollout.stop == Stop.SATISFIED and done.rollout.verdict == Verdict.SATISFIED, task.id


def test_washing_starts_from_the_dirty_mug_the_setup_made(kitchen):
    task = find_task("wash-mug")
    done = trial(kitchen, task)
    assert [s.attempt.atom.text for s in done.rollout.steps] == [
        "pick_up(mug)", "put(mug, sink)", "turn_on(faucet)", "turn_off(faucet)"]
    sink = done.rollout.steps[1].attempt.calls[-1].action["objectId"]
    assert sink.endswith("|SinkBasin")  # "sink" is the basin things go in


def test_a_goal_is_checked_on_the_final_state_not_the_formula(kitchen):
    # The formula holds (the potato went into the microwave) but nobody turned it on.
    task = find_task("microwave-potato")
    events = list(run_trial(kitchen, parse("F(open(microwave) & F(pick_up(potato) & F(put(potato, microwave) & "
                                           "F close(microwave))))"), task.scene, task))
    done = events[-1].trial
    assert done.rollout.verdict == Verdict.SATISFIED and not done.goal.met and not done.success


OBJECTS = [
    {"objectId": "Bread|1", "objectType": "Bread", "parentReceptacles": ["CounterTop|1"], "isCooked": False},
    {"objectId": "Tomato|2|TomatoSliced_0", "objectType": "TomatoSliced", "parentReceptacles": ["Plate|3"],
     "isCooked": False, "temperature": "Cold"},
    {"objectId": "Plate|3", "objectType": "Plate", "parentReceptacles": ["CounterTop|1"]},
    {"objectId": "CounterTop|1", "objectType": "CounterTop", "parentReceptacles": None},
]


@pytest.mark.parametrize("condition, met", [
    (GoalCondition("Tomato", {"isSliced": True}), True),  # a slice counts as the sliced tomato
    (GoalCondition("Tomato", {"isSliced": True, "in": "Plate", "temperature": "Cold"}), True),
    (GoalCondition("Tomato", {"in": "CounterTop"}), False),  # on the plate, not directly on the counter
    (GoalCondition("Bread", {"isSliced": True}), False),
    (GoalCondition("Bread", {"in": "CounterTop|1"}), True),  # an objectId works as the receptacle
    (GoalCondition("Tomato|2", {"isCooked": False}), True),  # and as the object, with its pieces
    (GoalCondition("Apple", {"isCooked": False}), False),
])
def test_goal_conditions_on_thor_metadata(condition, met):
    assert condition_met(condition, OBJECTS) is met


def test_the_tasks_file_is_checked(tmp_path):
    bad = tmp_path / "tasks.toml"
    bad.write_text('[[task]]\nid = "x"\ninstruction = "X it."\nscene = "FloorPlan1"\ncategory = "heat"\n'
                   'source = "here"\ngoal = [{ object = "Potato", isBoiled = true }]\n')
    with pytest.raises(UserError, match="unknown: isBoiled"):
        load_tasks(bad)
    bad.write_text(bad.read_text().replace('category = "heat"', 'category = "bake"'))
    with pytest.raises(UserError, match="category must be one of"):
        load_tasks(bad)


def test_an_id_is_not_used_in_both_files(tmp_path, monkeypatch):
    (tmp_path / "tasks").mkdir()
    task = ('[[task]]\nid = "x"\ninstruction = "X it."\nscene = "FloorPlan1"\ncategory = "heat"\nsource = "here"\n'
            'goal = [{ object = "Potato", isCooked = true }]\n')
    for name in ("tasks.toml", "paraphrases.toml"):
        (tmp_path / "tasks" / name).write_text(task)
    monkeypatch.setenv("COOK2LTL_ASSETS", str(tmp_path))
    with pytest.raises(UserError, match="task ids used twice: x"):
        load_tasks()
