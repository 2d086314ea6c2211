from cook2ltl.domain.recipe import Connective, Label
from cook2ltl.parse import parse_recipe
from tests.fakes import ScriptedDependencies, ScriptedSpans


def parse(text, spans, arcs=None):
    return parse_recipe(text, ScriptedSpans(spans), ScriptedDependencies(arcs))


def signatures(recipe):
    return [[frame.signature() for frame in step.frames] for step in recipe.steps]


def test_one_frame_per_action_with_its_arguments():
    text = "Cook the penne in a pot for 2 minutes, then drain it over low heat."
    recipe = parse(text, {text: [("VERB", "Cook"), ("WHAT", "the penne"), ("WHERE", "a pot"), ("TIME", "2 minutes"),
                                 ("VERB", "drain"), ("WHAT", "it"), ("TEMP", "low heat")]})
    assert signatures(recipe) == [["cook(the penne, a pot, 2 minutes)", "drain(the penne, low heat)"]]
    assert recipe.steps[0].links == (Connective.AND,)


def test_arguments_before_the_first_verb_belong_to_it():
    text = "In a blender put the seltzer."
    recipe = parse(text, {text: [("WHERE", "a blender"), ("VERB", "put"), ("WHAT", "the seltzer")]})
    assert signatures(recipe) == [["put(the seltzer, a blender)"]]


def test_or_between_actions_shares_the_object():
    text = "Bake or grill the chicken."
    recipe = parse(text, {text: [("VERB", "Bake"), ("VERB", "grill"), ("WHAT", "the chicken")]})
    assert signatures(recipe) == [["bake(the chicken)", "grill(the chicken)"]]
    assert recipe.steps[0].links == (Connective.OR,)
    assert not any(arg.inferred for frame in recipe.steps[0].frames for arg in frame.what)


def test_one_verb_span_with_a_coordinator_is_split():
    text = "Butter or oil an 8-inch baking dish."
    recipe = parse(text, {text: [("VERB", "Butter or oil"), ("WHAT", "an 8-inch baking dish")]})
    step = recipe.steps[0]
    assert [frame.verb.text for frame in step.frames] == ["Butter", "oil"]
    assert [text[f.verb.start:f.verb.end] for f in step.frames] == ["Butter", "oil"]
    assert step.links == (Connective.OR,)
    assert all(frame.what[0].span.text == "an 8-inch baking dish" for frame in step.frames)


def test_negation_comes_from_the_parse():
    text = "Do not overmix the batter."
    recipe = parse(text, {text: [("VERB", "overmix"), ("WHAT", "the batter")]})
    assert recipe.steps[0].frames[0].negated
    assert recipe.steps[0].frames[0].signature() == "not overmix(the batter)"


def test_a_later_negation_does_not_negate_the_earlier_action():
    text = "Stir the sauce and do not boil it."
    recipe = parse(text, {text: [("VERB", "Stir"), ("WHAT", "the sauce"), ("VERB", "boil"), ("WHAT", "it")]})
    assert [frame.negated for frame in recipe.steps[0].frames] == [False, True]


def test_coordinated_objects_are_split_with_their_connective():
    text = "Add salt or pepper to the pot."
    arcs = {text: {"salt": ("dobj", "Add"), "pepper": ("conj", "salt"), "or": ("cc", "salt")}}
    recipe = parse(text, {text: [("VERB", "Add"), ("WHAT", "salt or pepper"), ("WHERE", "the pot")]}, arcs)
    frame = recipe.steps[0].frames[0]
    assert [argument.span.text for argument in frame.what] == ["salt", "pepper"]
    assert frame.objects_joined_by == Connective.OR
    assert [text[a.span.start:a.span.end] for a in frame.what] == ["salt", "pepper"]


def test_or_inside_an_argument_does_not_make_actions_alternatives():
    text = "Stir the soup until thick or creamy and serve."
    recipe = parse(text, {text: [("VERB", "Stir"), ("WHAT", "the soup"), ("TIME", "until thick or creamy"),
                                 ("VERB", "serve")]})
    assert recipe.steps[0].links == (Connective.AND,)


def test_missing_object_is_inferred_from_context_across_sentences():
    text = "Tear the cheese into pieces. Add to the pan. Heat until melted."
    recipe = parse(text, {
        "Tear the cheese into pieces.": [("VERB", "Tear"), ("WHAT", "the cheese"), ("HOW", "into pieces")],
        "Add to the pan.": [("VERB", "Add"), ("WHERE", "the pan")],
        "Heat until melted.": [("VERB", "Heat"), ("TIME", "until melted")],
    })
    add, heat = recipe.steps[1].frames[0], recipe.steps[2].frames[0]
    assert add.what[0].inferred and add.what[0].span.text == "the cheese"
    assert heat.what[0].inferred and heat.what[0].span.start == text.index("the cheese")


def test_no_context_leaves_the_object_empty():
    text = "Preheat to 350 F."
    recipe = parse(text, {text: [("VERB", "Preheat"), ("TEMP", "350 F")]})
    assert recipe.steps[0].frames[0].what == ()


def test_span_offsets_are_absolute():
    text = "Boil water. Add the pasta."
    recipe = parse(text, {"Boil water.": [("VERB", "Boil"), ("WHAT", "water")],
                          "Add the pasta.": [("VERB", "Add"), ("WHAT", "the pasta")]})
    for step in recipe.steps:
        for span in step.spans:
            assert text[span.start:span.end] == span.text
    assert recipe.steps[1].spans[0].label == Label.VERB


def test_a_negation_inside_the_verb_span_is_trimmed_and_kept_as_negation():
    text = "Do not boil the sauce."
    recipe = parse(text, {text: [("VERB", "Do not boil"), ("WHAT", "the sauce")]})
    frame = recipe.steps[0].frames[0]
    assert frame.verb.text == "boil" and text[frame.verb.start:frame.verb.end] == "boil"
    assert frame.negated and frame.signature() == "not boil(the sauce)"


def test_a_negation_inside_an_argument_negates_no_action():
    text = "Stir the batter until not lumpy and pour it."
    recipe = parse(text, {text: [("VERB", "Stir"), ("WHAT", "the batter"), ("TIME", "until not lumpy"),
                                 ("VERB", "pour"), ("WHAT", "it")]})
    assert [frame.negated for frame in recipe.steps[0].frames] == [False, False]


def test_a_pronoun_object_is_resolved_like_a_missing_one():
    text = "Drain the pasta and rinse it."
    recipe = parse(text, {text: [("VERB", "Drain"), ("WHAT", "the pasta"), ("VERB", "rinse"), ("WHAT", "it")]})
    rinse = recipe.steps[0].frames[1]
    assert [(a.span.text, a.inferred) for a in rinse.what] == [("the pasta", True)]


def test_a_pronoun_with_nothing_before_it_stays():
    text = "Rinse it."
    recipe = parse(text, {text: [("VERB", "Rinse"), ("WHAT", "it")]})
    assert [(a.span.text, a.inferred) for a in recipe.steps[0].frames[0].what] == [("it", False)]


def test_the_particle_of_a_phrasal_verb_joins_the_verb():
    """"Turn the stove on" and "turn off the heat" (a particle, however the parse attaches it) are their own
    verbs; "spread on the bread" keeps "on the bread" as where the spread goes."""
    after = "Turn the stove on."
    recipe = parse(after, {after: [("VERB", "Turn"), ("WHAT", "the stove")]}, {after: {"on": ("prt", "Turn")}})
    assert signatures(recipe) == [["turn on(the stove)"]]
    before = "Switch off the heat."
    recipe = parse(before, {before: [("VERB", "Switch"), ("WHAT", "the heat")]}, {before: {"off": ("prep", "Switch")}})
    assert signatures(recipe) == [["switch off(the heat)"]]
    place = "Spread on the bread."
    recipe = parse(place, {place: [("VERB", "Spread"), ("WHERE", "on the bread")]}, {place: {"on": ("prep", "Spread")}})
    assert signatures(recipe) == [["spread(on the bread)"]]
    inside = "Stir in the cheese."
    recipe = parse(inside, {inside: [("VERB", "Stir"), ("WHAT", "the cheese")]}, {inside: {"in": ("prt", "Stir")}})
    assert signatures(recipe) == [["stir(the cheese)"]]


def test_a_switch_the_span_model_took_for_a_place_is_the_verbs_particle():
    """The span model reads "on" as the start of a place; after turn or switch it is the switch."""
    before = "Switch on the toaster."
    recipe = parse(before, {before: [("VERB", "Switch"), ("WHERE", "on the toaster")]},
                   {before: {"on": ("prep", "Switch"), "toaster": ("pobj", "on")}})
    assert signatures(recipe) == [["switch on(the toaster)"]]
    after = "Turn the faucet on."
    recipe = parse(after, {after: [("VERB", "Turn"), ("WHAT", "the faucet"), ("WHERE", "on")]},
                   {after: {"on": ("prt", "Turn")}})
    assert signatures(recipe) == [["turn on(the faucet)"]]
    place = "Place on a plate."
    recipe = parse(place, {place: [("VERB", "Place"), ("WHERE", "on a plate")]}, {place: {"on": ("prep", "Place")}})
    assert signatures(recipe) == [["place(on a plate)"]]


def test_a_direct_object_the_span_model_missed_is_the_what():
    text = "Heat up your coffee in the microwave, then stir."
    arcs = {"up": ("prt", "Heat"), "your": ("poss", "coffee"), "coffee": ("dobj", "Heat"), "in": ("prep", "Heat")}
    recipe = parse(text, {text: [("VERB", "Heat"), ("WHERE", "in the microwave"), ("TIME", "then"),
                                 ("VERB", "stir")]}, {text: arcs})
    (heat, stir) = recipe.steps[0].frames
    assert heat.signature() == "heat up(your coffee, in the microwave)" and not heat.time
    assert heat.what[0].span.text == "your coffee"
