"""The seed of the draws (`rbi.spec.uncertain.generator`): a seed numpy refuses is exit 2 and one
line naming --seed, in `rbi uncertainty --method monte-carlo` and `rbi simulate --draws` alike,
not an internal error."""

from __future__ import annotations

import json

import pytest

import rbi
from tests.conftest import one_line_exit_2, run_rbi_inprocess

SPEC = 'parts: [{name: p, shape: sphere, radius: 0.1, mass: "1 ± 0.1", center: [0, 0, 0.1]}]\n'


@pytest.fixture
def spec(tmp_path):
    path = tmp_path / "dot.yaml"
    path.write_text(SPEC)
    return path


@pytest.mark.parametrize(
    "args",
    [
        ("uncertainty", "--method", "monte-carlo", "--samples", "100", "--seed", "-1"),
        ("simulate", "--spin", "10", "--duration", "0.1", "--draws", "3", "--seed", "-1"),
    ],
)
def test_a_negative_seed_is_exit_2_naming_it(spec, args):
    proc = run_rbi_inprocess(args[0], str(spec), *args[1:])
    one_line_exit_2(proc, "--seed")


def test_the_api_refuses_it_too_and_a_seed_gives_the_same_draws(spec):
    body = rbi.load(spec)
    with pytest.raises(rbi.ArgumentError, match="seed"):
        body.uncertainty(method="monte-carlo", samples=100, seed=-1)
    first, again = (body.uncertainty(of="mass", method="monte-carlo", samples=1000, seed=7) for _ in range(2))
    assert json.dumps(first.to_dict()) == json.dumps(again.to_dict())
    # 1000 draws of a 1 ± 0.1 mass: their standard deviation within 10 % of 0.1
    assert first.to_dict()["quantities"][0]["u"] == pytest.approx(0.1, rel=0.1)
