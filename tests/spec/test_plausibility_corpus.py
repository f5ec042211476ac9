"""The unit-slip warning on a corpus of real objects (tests/spec/plausibility_corpus.py): written
in SI it is never warned (false-positive rate 0); written in mm/g, mm/kg, cm/g and in/lb without
``units:``, the share of slips that get exactly the units they were written in is measured and
printed per unit pair (``pytest -s``), for the first 63 objects (the rule was shaped on them),
for the 33 added in the second round (a hold-out, measured with the rule already set), the 32
added in the third round and the 58 added in the fourth (second and third hold-outs, each added
before any further change to the rule).

Issue 26 asks for 90 %. The model's numbers are a maximum-likelihood fit to the first 128
objects (refitted by the last test below), the third hold-out measured before each change to the
rule and after it. Measured now: 90.2 % on all 186 (88.5 % on the first 63, 93.9 % and 92.2 % on
the first two hold-outs, 90.8 % on the 128 the model was fitted to, 88.8 % on the third
hold-out; 89.1 % with every number rounded to 3 digits). The steps: 88.3 % with the hand-set
model (third hold-out 87.5 %); 89.8 % (88.8 %) with its numbers fitted by maximum likelihood and a
fixed share of handbook materials; 90.2 % (88.8 %) with that share falling with size, every
number fitted as one mixture (log-likelihood of the 134 calibration parts 14.4 above the same
mixture with a fixed share, for one more number).
The floors below are the measured numbers. What no rule on densities and sizes can tell apart
(docs/spec.md): a pair of units differs from another by a factor on density and one on size, so
a part a centimetre across that is not exactly a handbook material (a coin, a bar drawn as a
box) in mm/g reads as a hollow body in in/lb, a light body (foam, a chair drawn by its outline)
in cm/g as a solid in in/lb, and a body metres across (a car, a satellite) in in/lb as a part a
few centimetres across in mm/g."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import optimize, stats

import rbi
import rbi.spec.plausibility as P
from tests.spec.plausibility_corpus import (
    FIRST_ADDED_LATER,
    OBJECTS,
    SECOND_ADDED_LATER,
    SLIPS,
    THIRD_ADDED_LATER,
    si_parts,
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
    assert every["mm/g"] >= 0.881 and every["mm/kg"] >= 1.0 and every["cm/g"] >= 0.913, every
    assert every["in/lb"] >= 0.811 and every["all"] >= 0.901, every
    assert rates["first 63"]["all"] >= 0.884 and rates["hold-out"]["all"] >= 0.938, rates
    assert rates["second hold-out"]["all"] >= 0.921 and rates["third hold-out"]["all"] >= 0.887, rates


def test_slips_rounded_to_three_digits_get_the_right_hint_less_often():
    """Written as a person rounds them (3 significant digits), sizes and masses no longer meet a
    handbook density to 0.1 %, so only density and size decide: measured 89.1 % on all 186
    (in/lb 80.6 %; third hold-out 88.4 %), against 90.2 % for the exact numbers; no SI object is
    warned either way."""
    rates = _hint_rates(digits=3)
    every = rates["all objects"]
    assert every["in/lb"] >= 0.806 and every["all"] >= 0.891, every
    assert rates["third hold-out"]["all"] >= 0.883, rates


def _calibration_parts() -> tuple[np.ndarray, np.ndarray]:
    """log10 size (cube root of the volume, m) and log10 density (kg/m³) of every part of the
    objects the model was fitted to: those before the third hold-out."""
    names = [o[0] for o in OBJECTS]
    parts = [p for entry in OBJECTS[: names.index(THIRD_ADDED_LATER)] for p in si_parts(entry)]
    return np.log10([v for v, _ in parts]) / 3, np.log10([m / v for v, m in parts])


def test_the_model_is_the_maximum_likelihood_fit_to_the_calibration_corpus():
    """The density model's numbers (typical density at 1 m, its fall per decade of size, the
    size above which it falls no further, the spread; below, it stays at steel's 7,850 kg/m³)
    and the share of handbook materials (logistic in log10 size: the size where it is one half,
    its slope) are refitted here by maximum likelihood, as one mixture, to the 134 parts of the
    first 128 objects and must be the module's to the digits it gives; so must the size
    distribution's (logistic in log10 size), fitted on its own."""
    sizes, densities = _calibration_parts()
    steel = math.log10(7850.0)
    width, known = P.MATERIAL_MATCH_DECADES, np.array(P._REFERENCE_DECADES)
    spike = (np.abs(densities[:, None] - known) < width).sum(axis=1) / (2 * width * len(known))

    def minus_log_likelihood(p):
        typical, thinning, largest, spread, half, slope = p
        mean = np.minimum(typical - thinning * np.minimum(sizes, largest), steel)
        share = 1 / (1 + np.exp(slope * (sizes - half)))
        return -np.log(share * spike + (1 - share) * stats.norm.pdf(densities, mean, abs(spread))).sum()

    start = [2.5, 0.5, 0.0, 0.7, -2.0, 1.0]
    options = {"maxiter": 40_000, "xatol": 1e-7, "fatol": 1e-10}
    fit = optimize.minimize(minus_log_likelihood, start, method="Nelder-Mead", options=options)
    typical, thinning, largest, spread, half, slope = fit.x
    assert P.TYPICAL_DENSITY_KG_M3 == pytest.approx(10**typical, rel=0.01)
    assert P.STRUCTURE_THINNING == pytest.approx(thinning, abs=0.005)
    assert P.STRUCTURE_SIZES_M[1] == pytest.approx(10**largest, rel=0.02)
    assert P.DENSITY_SPREAD_DECADES == pytest.approx(abs(spread), abs=0.005)
    assert P.MATERIAL_HALF_SIZE_M == pytest.approx(10**half, rel=0.02)
    assert P.MATERIAL_SHARE_SLOPE == pytest.approx(slope, abs=0.01)
    smallest = P.TYPICAL_DENSITY_KG_M3 * P.STRUCTURE_SIZES_M[0] ** -P.STRUCTURE_THINNING
    assert smallest == pytest.approx(7850, rel=0.02)  # the fall stops at steel's density
    centre, scale = stats.logistic.fit(sizes)
    assert P.BODY_SIZE_M == pytest.approx(10**centre, rel=0.05)
    assert P.BODY_SIZE_SPREAD_DECADES == pytest.approx(scale, abs=0.005)


def test_the_share_of_handbook_materials_falls_with_size():
    """Among the calibration parts, those between 3 mm and 3 cm are far more often exactly a
    handbook material than those over 30 cm (15 of 27 against 3 of 38); the fitted share says the
    same."""
    sizes, densities = _calibration_parts()
    exact = np.array(
        [any(abs(d - k) < P.MATERIAL_MATCH_DECADES for k in P._REFERENCE_DECADES) for d in densities]
    )
    small, large = (sizes >= -2.5) & (sizes < -1.5), sizes >= -0.5
    assert exact[small].mean() > 0.5 > 0.1 > exact[large].mean()
    assert P.material_share(-2.0) > 0.5 > 0.1 > P.material_share(0.0)
