"""`rbi simulate --plot`: the four panels for a top (also upright and asleep) and a free body
(the rotation they rest on, :func:`rbi.core.rotation.rotate`, is checked against scipy in
tests/core/test_rotation.py)."""

from __future__ import annotations

import json

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from rbi.core.rotation import rotate  # noqa: E402
from rbi.sim import api as kernel  # noqa: E402
from tests.conftest import BODIES, run_rbi_inprocess  # noqa: E402


@pytest.mark.parametrize(
    "args",
    [
        ["top.yaml", "--spin", "200", "--tilt", "0.01", "--duration", "1"],
        [
            "top.yaml",
            "--spin",
            "300",
            "--duration",
            "0.5",
        ],  # upright and asleep: the axis never leaves vertical
        ["tbar.yaml", "--omega", "0.01,0.01,3", "--duration", "2"],  # free body
    ],
)
def test_plot_is_written(tmp_path, bodies, args):
    from PIL import Image

    out = tmp_path / "run.png"
    proc = run_rbi_inprocess("simulate", bodies / args[0], *args[1:], "--plot", out)
    assert proc.returncode == 0, proc.stderr
    image = np.asarray(Image.open(out).convert("RGB"))
    assert image.shape[0] > 500 and image.shape[1] > 800


def test_the_intermediate_axis_of_a_free_body_flips_against_the_angular_momentum(bodies, tmp_path):
    """The quantity the free-body panel draws: the T-handle spun near its intermediate axis (z)
    turns that axis from along the angular momentum to against it (Dzhanibekov effect)."""
    import csv

    out = tmp_path / "run.csv"
    proc = run_rbi_inprocess(
        "simulate",
        bodies / "tbar.yaml",
        "--omega",
        "0.01,0.01,3",
        "--duration",
        "20",
        "--samples",
        "2001",
        "--out",
        out,
    )
    assert proc.returncode == 0, proc.stderr
    rows = list(csv.DictReader(out.open()))
    q = np.array([[float(r[k]) for k in ("qw", "qx", "qy", "qz")] for r in rows])
    z_world = rotate(q, [0.0, 0.0, 1.0])
    # ω starts almost along z, so the fixed angular momentum starts almost along the body z axis
    angle = np.degrees(np.arccos(np.clip(z_world @ z_world[0], -1, 1)))
    assert angle.max() > 170.0


def test_simulate_plot_integrates_once(tmp_path, monkeypatch):
    # the plot's denser samples were a second run of the whole integration
    calls = []
    compiled = kernel._run_compiled

    def counted(*args, **kwargs):
        calls.append(args[3].size)  # the sample times
        return compiled(*args, **kwargs)

    monkeypatch.setattr(kernel, "_run_compiled", counted)
    args = (
        "simulate",
        BODIES / "top.yaml",
        "--spin",
        "150",
        "--tilt",
        "5",
        "--duration",
        "0.5",
        "--samples",
        "41",
    )
    plain = _json(*args, "--no-error-estimate")
    calls.clear()
    drawn = _json(*args, "--no-error-estimate", "--plot", tmp_path / "run.png")
    assert (tmp_path / "run.png").stat().st_size > 0
    assert len(calls) == 1 and calls[0] > 8000  # one integration, sampled for the plot too
    # the run's own samples are the same bit for bit (dense output does not change the steps)
    same = ("wall_seconds", "load_seconds", "rhs_evals")
    assert {k: v for k, v in drawn.items() if k not in same} == {
        k: v for k, v in plain.items() if k not in same
    }


def _json(*args):
    proc = run_rbi_inprocess(*args, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


def test_a_plot_through_a_link_to_the_out_file_is_refused_naming_both_options(tmp_path, bodies):
    """`--plot` a symlink to the `--out` file: one file for two outputs, named as options
    (`rbi sweep` says the same); the CSV already there is left as it was."""
    out = tmp_path / "run.csv"
    out.write_text("mine\n")
    (tmp_path / "run.png").symlink_to(out)
    proc = run_rbi_inprocess(
        "simulate", bodies / "top.yaml", "--duration", "0.1", "--out", out, "--plot", tmp_path / "run.png"
    )
    assert proc.returncode == 2 and proc.stdout == ""
    assert proc.stderr.strip().splitlines() == [
        f"rbi: --plot: {tmp_path / 'run.png'}: is also the --out output of this run; give each output its own file"
    ]
    assert out.read_text() == "mine\n"
