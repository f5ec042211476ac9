"""The unit-slip warning on a corpus of real objects (tests/spec/plausibility_corpus.py): written
in SI it is never warned (false-positive rate 0); written in mm/g, mm/kg, cm/g and in/lb without
``units:``, the share of slips that get exactly the units they were written in is measured and
printed per unit pair (``pytest -s``), for the first 63 objects (the rule was shaped on them),
for the 33 added in the second round (a hold-out, measured with the rule already set), the 32
added in the third round and the 58 added in the fourth (second and third hold-outs, each added
before any further change to the rule).

Issue 26 asks for 90 %. Measured with the rule as it stood when the third hold-out was added:
88.3 % on all 186 (86.5 % on the first 63, 92.4 %, 89.1 % and 87.5 % on the hold-outs; 87.4 %
with every number rounded to 3 digits); the floors below are those measured numbers. What no
rule on densities and sizes can tell apart (docs/spec.md): a pair of units differs from another
by a factor on density and one on size, so a part a centimetre across that is not exactly a
handbook material (a coin, a bar drawn as a box) in mm/g reads as a hollow body in in/lb, a
light body (foam, a chair drawn by its outline) in cm/g as a solid in in/lb, and a body metres
across (a car, a satellite) in in/lb as a part a few centimetres across in mm/g."""

from __future__ import annotations

import pytest

import rbi
from tests.spec.plausibility_corpus import (
    FIRST_ADDED_LATER,
    OBJECTS,
    SECOND_ADDED_LATER,
    SLIPS,
    THIRD_ADDED_LATER,
    spec,
)


def test_the_corpus_is_at_least_50_real_objects():
    assert len(OBJECTS) >= 50 and len({o[0] for o in OBJECTS}) == len(OBJECTS)


@pytest.mark.parametrize("digits", [None, 3])
def test_no_object_written_in_si_is_warned(digits):
    warned = [(o[0], w) for o in OBJECTS for w in rbi.load(spec(o, digits=digits)).warnings]
    rate = len(warned) / len(OBJECTS)
    print(
        f"\nunit-slip corpus, {digits or 'all'} digits: false-positive rate {rate:.1%} ({len(warned)} of {len(OBJECTS)})"
    )
    assert warned == []


def _right(entry, units, expected, digits=None) -> bool:
    warnings = rbi.load(spec(entry, units["length"], units["mass"], digits)).warnings
    return len(warnings) == 1 and warnings[0].endswith(expected)


def _hint_rates(digits: int | None = None) -> dict[str, dict[str, float]]:
    """Share of right hints per unit pair and overall ('all'), for every object, the first 63
    and the three hold-outs; with ``digits``, every number rounded to that many significant
    digits."""
    names = [o[0] for o in OBJECTS]
    first, second = names.index(FIRST_ADDED_LATER), names.index(SECOND_ADDED_LATER)
    third = names.index(THIRD_ADDED_LATER)
    groups = {
        "all objects": OBJECTS,
        "first 63": OBJECTS[:first],
        "hold-out": OBJECTS[first:second],
        "second hold-out": OBJECTS[second:third],
        "third hold-out": OBJECTS[third:],
    }
    right = {slip: {o[0]: _right(o, *SLIPS[slip], digits) for o in OBJECTS} for slip in SLIPS}
    rates = {}
    for group, objects in groups.items():
        rates[group] = {slip: sum(right[slip][o[0]] for o in objects) / len(objects) for slip in SLIPS}
        rates[group]["all"] = sum(rates[group].values()) / len(SLIPS)
        print(
            f"\n{digits or 'all'} digits, {group} ({len(objects)}): "
            + ", ".join(f"{k} {v:.1%}" for k, v in rates[group].items())
        )
    print("wrong: " + "; ".join(f"{s} {name}" for s in SLIPS for name, ok in right[s].items() if not ok))
    return rates


def test_slips_get_exactly_the_right_hint():
    rates = _hint_rates()
    every = rates["all objects"]
    assert every["mm/g"] >= 0.897 and every["mm/kg"] >= 1.0 and every["cm/g"] >= 0.844, every
    assert every["in/lb"] >= 0.790 and every["all"] >= 0.883, every
    assert rates["first 63"]["all"] >= 0.865 and rates["hold-out"]["all"] >= 0.924, rates
    assert rates["second hold-out"]["all"] >= 0.890 and rates["third hold-out"]["all"] >= 0.875, rates


def test_slips_rounded_to_three_digits_get_the_right_hint_less_often():
    """Written as a person rounds them (3 significant digits), sizes and masses no longer meet a
    handbook density to 0.1 %, so only density and size decide: measured 87.4 % on all 186
    (in/lb 79.0 %), against 88.3 % for the exact numbers; no SI object is warned either way."""
    every = _hint_rates(digits=3)["all objects"]
    assert every["in/lb"] >= 0.790 and every["all"] >= 0.873, every
