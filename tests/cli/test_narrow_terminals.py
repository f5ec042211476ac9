"""Tables at 60, 80 and 120 columns: no number cut, split across lines or shortened to `…`,
checked against the JSON of the same run (every number a table prints is one of the JSON's
numbers, to the digits printed, up to a power of ten: tables print ×10⁻⁴ scales and
percentages); rounding noise prints as 0; energy in J for an SI spec."""

from __future__ import annotations

import bisect
import contextlib
import io
import json
import math
import re
from pathlib import Path

import pytest

from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as rbi

WIDTHS = (60, 80, 120)
BAD_PARTS = "parts:\n  - {name: a, shape: point, mass: -1, position: [0, 0, 0]}\n"

COMMANDS = {
    "inertia": ["inertia", BODIES / "top_bolted.yaml"],
    "inertia noise": ["inertia", BODIES / "wheel_with_holes.yaml", "--units", "SI"],
    "principal": ["principal", BODIES / "cubesat.yaml"],
    "parts": ["parts", BODIES / "robot_link.yaml"],
    "momentum": ["momentum", BODIES / "top_bolted.yaml", "--omega", "0,0,100"],
    "dynamics": [
        "dynamics",
        BODIES / "top.yaml",
        "--about",
        "pivot",
        "--omega",
        "0,0,200",
        "--alpha",
        "1,0,0",
    ],
    "simulate": ["simulate", BODIES / "top_bolted.yaml", "--spin", "200", "--duration", "1"],
    "sweep": ["sweep", BODIES / "top.yaml", "--spin", "180:240:4", "--tilt", "0.01", "--duration", "1"],
    "sweep spread": [
        "sweep",
        BODIES / "top_bolted.yaml",
        "--mass-properties",
        "--runs",
        "40",
        "--seed",
        "1",
        "--vary",
        "parts.bolt.position[0]=uniform(0.039,0.041)",
    ],
    "check": ["check", BODIES / "robot_link.yaml"],
    "several files": ["principal", BODIES / "top.yaml", BODIES / "tbar.yaml"],
}

_NUMBER = re.compile(
    r"(?<![\w.·^/])[-−]?(?:\d{1,3}(?:,\d{3})+|\d+)(?:\.\d+)?(?:e[-+]?\d+)?(?![\w⁰¹²³⁴⁵⁶⁷⁸⁹⁻.])"
)


def numbers_in(value) -> list[float]:
    """Every number of a JSON value, those inside its strings too (messages, verdicts)."""
    if isinstance(value, dict):
        return [x for v in value.values() for x in numbers_in(v)]
    if isinstance(value, list):
        return [x for v in value for x in numbers_in(v)]
    if isinstance(value, bool) or value is None:
        return []
    if isinstance(value, (int, float)):
        return [float(value)]
    return [float(token.replace(",", "").replace("−", "-")) for token in _NUMBER.findall(str(value))]


def _mantissa(x: float) -> float:
    return abs(x) / 10 ** math.floor(math.log10(abs(x)))


class Known:
    """The numbers of a JSON output, searchable by their digits (their mantissas)."""

    def __init__(self, values):
        self.mantissas = sorted(_mantissa(x) for x in values if x and math.isfinite(x))

    def holds(self, token: str) -> bool:
        printed = float(token.replace(",", "").replace("−", "-"))
        if printed == 0:
            return True
        digits = token.split("e")[0].lstrip("-−").replace(",", "")
        decimals = len(digits.split(".")[1]) if "." in digits else 0
        exponent = int(token.split("e")[1]) if "e" in token else 0
        half_step = 0.5 * 10.0 ** (exponent - decimals) * 1.000001
        mantissa, scale = _mantissa(printed), 10 ** math.floor(math.log10(abs(printed)))
        tolerance = half_step / scale
        for target in (mantissa, mantissa * 10, mantissa / 10):
            i = bisect.bisect_left(self.mantissas, target - tolerance)
            if i < len(self.mantissas) and self.mantissas[i] <= target + tolerance:
                return True
        return False


LINES_NOT_TABLES = ("validate",)
"""Commands whose output is lines (one message a problem) that a terminal wraps: their
numbers are checked, not their width (an error line stays one line)."""


def check_printed(text: str, known: Known, width: int, label: str) -> None:
    for line in text.splitlines():
        if label not in LINES_NOT_TABLES:
            assert len(line.rstrip()) <= width, (label, width, line)
        assert not re.search(r"[\d.]…|…\d", line), (label, width, "shortened", line)
        assert line.count("[") == line.count("]"), (label, width, "split across lines", line)
        if "wall time" in line or line.startswith(("- Date", "rbi bench")):
            continue  # timings differ between the table's run and the JSON's
        for token in _NUMBER.findall(line):
            assert known.holds(token), (label, width, f"{token} is not a number of the JSON", line)


def _json(args) -> Known:
    proc = rbi(*args, "--format", "json")
    assert proc.returncode in (0, 1, 2), proc.stderr
    objects = [json.loads(line) for line in proc.stdout.splitlines()]
    return Known([x for o in objects for x in numbers_in(o)] + [x for o in objects for x in _deviations(o)])


def _deviations(result) -> list[float]:
    """`rbi check`'s table shows each component's deviation |actual − expected|; its JSON
    gives both arrays (and the largest deviation)."""
    out = []
    for check in result.get("checks", []) if isinstance(result, dict) else []:
        import numpy as np

        out += np.abs(np.subtract(check["actual"], check["expected"], dtype=float)).ravel().tolist()
    return out


@pytest.mark.parametrize("name", COMMANDS)
def test_every_number_printed_is_whole_at_every_width(name, monkeypatch):
    args = COMMANDS[name]
    known = _json(args)
    for width in WIDTHS:
        monkeypatch.setenv("COLUMNS", str(width))
        proc = rbi(*args)
        assert proc.returncode in (0, 1), proc.stderr
        check_printed(proc.stdout, known, width, name)


def test_validate_at_every_width(tmp_path, monkeypatch):
    bad = tmp_path / "bad.yaml"
    bad.write_text(BAD_PARTS)
    known = _json(["validate", BODIES / "top.yaml", bad])
    for width in WIDTHS:
        monkeypatch.setenv("COLUMNS", str(width))
        check_printed(rbi("validate", BODIES / "top.yaml", bad).stdout, known, width, "validate")


def test_bench_tables_at_every_width(monkeypatch):
    """The tables of a real `rbi bench --quick` result (saved: a run takes half a minute)."""
    from rbi.cli.bench_command import _tables
    from rbi.cli.render import print_table

    result = json.loads((Path(__file__).parents[1] / "data" / "bench" / "quick_result.json").read_text())
    known = Known(
        numbers_in(result)
        + numbers_in(__import__("rbi.bench.report", fromlist=["x"]).markdown(result, "", None))
    )
    for width in WIDTHS:
        monkeypatch.setenv("COLUMNS", str(width))
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed):
            print_table(_tables(result))
        check_printed(printed.getvalue(), known, width, "bench")
        words = " ".join(printed.getvalue().split())
        for target in result["targets"]:  # long texts wrap between words, never cut off
            assert " ".join(str(target["detail"]).split()) in words, (width, target["detail"])


def test_rounding_noise_prints_as_zero_and_json_keeps_it(monkeypatch):
    """The wheel with holes has an Ixy of about -3e-22 kg·m² beside 5e-3: noise, 1e-19 of it."""
    args = ["inertia", BODIES / "wheel_with_holes.yaml", "--units", "SI"]
    inertia = json.loads(rbi(*args, "--format", "json").stdout)["inertia"]
    assert inertia[0][1] != 0.0 and abs(inertia[0][1]) < 1e-12 * abs(inertia[2][2])
    monkeypatch.setenv("COLUMNS", "80")
    rows = [line.split() for line in rbi(*args).stdout.splitlines() if line.startswith((" x ", " y "))]
    assert rows[-2][2] == "0" and rows[-1][1] == "0", rows
    from rbi.text import vector_text

    assert (
        vector_text([1.0, 3.6e-37, -2e-13], scale=0.0) == "[1, 0, 0]"
        and vector_text([1e-20, 0, 0], scale=0.0) == "[1e-20, 0, 0]"
    )


def test_energy_is_in_joules_for_an_si_spec_and_every_header_has_its_unit():
    momentum = rbi("momentum", BODIES / "top_bolted.yaml", "--omega", "0,0,100").stdout
    assert re.search(r"kinetic energy\s+J\s", momentum)
    flywheel = rbi("momentum", BODIES / "flywheel.yaml", "--omega", "0,0,100").stdout
    assert "g·mm²/s²" in flywheel
    simulate = rbi("simulate", BODIES / "top.yaml", "--spin", "200", "--duration", "0.1").stdout
    assert re.search(r"energy\s+J\s", simulate) and "kg·m²/s²" not in simulate + momentum
