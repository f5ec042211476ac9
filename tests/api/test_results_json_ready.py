"""Every API result's ``to_dict()`` is JSON-ready (``json.dumps`` takes it: lists, floats, str,
None; no numpy) and equals its command's ``--format json`` less ``"file"``; ``to_pandas()`` is
a DataFrame, ``print()`` a table and ``_repr_html_`` an HTML table (contract, fifth round,
"Seams")."""

from __future__ import annotations

import json

import pytest

import rbi
from tests.conftest import BODIES, run_rbi_inprocess

SPEC = """
name: bolted
pivot: [0, 0, 0]
parts:
  - {name: disc, shape: cylinder, radius: 0.05, start: [0, 0, 0.02], end: [0, 0, 0.03], mass: "0.5 ± 1%"}
  - {name: bolt, shape: point, mass: 0.01, position: ["0.04 ± 0.001", 0, 0.025]}
"""


def command_json(*args: str) -> dict:
    proc = run_rbi_inprocess(*args, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    out = json.loads(proc.stdout)
    out.pop("file", None)
    return out


def faces(result) -> dict:
    data = result.to_dict()
    assert json.loads(json.dumps(data)) == data  # JSON-ready: no numpy arrays or scalars
    assert type(result.to_pandas()).__name__ == "DataFrame"
    text = str(result)
    assert not text.startswith(type(result).__name__ + "(") and "─" in text  # a table, not a repr
    assert "<table" in result._repr_html_()
    return data


def untimed(data):
    """``data`` without its wall-clock times, which differ between two runs."""
    if isinstance(data, dict):
        return {k: untimed(v) for k, v in data.items() if "seconds" not in k}
    return [untimed(v) for v in data] if isinstance(data, list) else data


@pytest.fixture
def spec(tmp_path):
    path = tmp_path / "bolted.yaml"
    path.write_text(SPEC)
    return path


def test_mass_results_are_their_commands_json(spec):
    body = rbi.load(spec)
    assert faces(body) == command_json("inertia", str(spec))
    principal = faces(body.principal())
    assert principal == command_json("principal", str(spec))
    # independent numbers: the disc's 0.5 kg ± 1 % and the bolt's 0.01 kg give u(mass) = 0.005
    assert principal["uncertainty"]["mass"] == pytest.approx(0.005, rel=1e-12)
    assert faces(body.parts()) == command_json("parts", str(spec))
    assert faces(body.momentum(omega=[0, 0, 10])) == command_json("momentum", str(spec), "--omega", "0,0,10")
    assert faces(body.uncertainty()) == command_json("uncertainty", str(spec))


def test_robot_results_are_their_commands_json():
    urdf = BODIES / "two_link_arm.urdf"
    assert faces(rbi.audit(urdf)) == command_json("audit", str(urdf))
    assert faces(rbi.import_robot(urdf)) == command_json("import", str(urdf))


def test_run_results_are_their_commands_json(spec):
    body = rbi.load(spec)
    run = rbi.simulate(body, spin=100, duration=0.2, samples=11)
    cli = command_json("simulate", str(spec), "--spin", "100", "--duration", "0.2", "--samples", "11")
    assert untimed(faces(run)) == untimed(cli)
    table = rbi.sweep(body, spin=[50, 100], duration=0.2, samples=11, workers=1)
    assert untimed(faces(table)) == untimed(
        command_json(
            "sweep", str(spec), "--spin", "50:100:2", "--duration", "0.2", "--samples", "11", "--workers", "1"
        )
    )
