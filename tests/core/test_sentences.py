import pytest

from cook2ltl.preprocess import split_sentences


def texts(text: str) -> list[str]:
    return [sentence.text for sentence in split_sentences(text)]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Preheat the oven to 350 F. Butter the dish.", ["Preheat the oven to 350 F.", "Butter the dish."]),
        ("Bake at 350 F. for 20 min. or until done. Serve.", ["Bake at 350 F. for 20 min. or until done.", "Serve."]),
        ("Cool approx. 5 min. Slice.", ["Cool approx. 5 min.", "Slice."]),
        ("Add 1 tsp. salt and 1.5 c. flour. Stir.", ["Add 1 tsp. salt and 1.5 c. flour.", "Stir."]),
        ("Simmer e.g. Over low heat. Stir!", ["Simmer e.g. Over low heat.", "Stir!"]),
        ("1. Boil water.\n2) Add pasta\n- Drain", ["Boil water.", "Add pasta", "Drain"]),
        ("Mix well! Serve hot?  ", ["Mix well!", "Serve hot?"]),
        ("", []),
        ("   \n\n ...", []),
    ],
)
def test_sentences_survive_cooking_abbreviations(text, expected):
    assert texts(text) == expected


def test_offsets_point_into_the_text_as_given():
    text = "  1. Whisk the eggs.  Fold in flour approx. 2 min.\r\nServe."
    for sentence in split_sentences(text):
        assert text[sentence.start:sentence.end] == sentence.text
