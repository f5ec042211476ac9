"""`rbi dynamics` against Newton–Euler worked by hand for the seed's top."""

import json

import numpy as np
import pytest

from tests.conftest import BODIES, run_rbi

TOP = BODIES / "top.yaml"
M, Z_COM = 0.5, 0.052
I_PIVOT_XX = 0.0016149333333333334  # expected.json: inertia about the tip
I_COM = np.diag([0.00026293333333333335, 0.00026293333333333335, 0.00019520000000000006])


def rbi_json(*args):
    proc = run_rbi("dynamics", TOP, *args, "--format", "json", check=True)
    return json.loads(proc.stdout)


def test_inverse_about_the_tip_gives_torque_and_holding_force():
    out = rbi_json("--about", "pivot", "--omega", "0,0,200", "--alpha", "1,0,0")
    # Spin along a principal axis through the tip: no gyroscopic term, τ = I_o α.
    assert out["torque"] == pytest.approx([I_PIVOT_XX, 0, 0], rel=1e-12, abs=1e-18)
    # F = m a_c, a_c = α × r + ω × (ω × r) with r = (0, 0, z_com) ∥ ω.
    assert out["force"] == pytest.approx([0, -M * Z_COM, 0], rel=1e-12, abs=1e-18)


def test_forward_about_the_tip_inverts_the_inverse():
    tau = [I_PIVOT_XX, 0.0002, -0.0001]
    out = rbi_json("--about", "pivot", "--omega", "3,-2,150", "--torque", ",".join(map(repr, tau)))
    back = rbi_json("--about", "pivot", "--omega", "3,-2,150", "--alpha", ",".join(map(repr, out["alpha"])))
    assert back["torque"] == pytest.approx(tau, rel=1e-10, abs=1e-15)
    assert back["force"] == pytest.approx(out["force"], rel=1e-10, abs=1e-15)


def test_forward_about_the_com_is_eulers_equation():
    w = np.array([1.0, 2.0, 3.0])
    tau = np.array([1e-4, -2e-4, 5e-5])
    out = rbi_json("--omega", "1,2,3", "--torque", "0.0001,-0.0002,0.00005", "--force", "1,0,0")
    expected_alpha = np.linalg.solve(I_COM, tau - np.cross(w, I_COM @ w))
    assert out["alpha"] == pytest.approx(expected_alpha.tolist(), rel=1e-10)
    assert out["point_acceleration"] == pytest.approx([1 / M, 0, 0], rel=1e-12)


def test_neither_or_both_modes_is_refused():
    for extra in ([], ["--alpha", "1,0,0", "--torque", "1,0,0"]):
        proc = run_rbi("dynamics", TOP, *extra)
        assert proc.returncode == 2
        assert "Traceback" not in proc.stderr and "--alpha" in proc.stderr


@pytest.mark.parametrize("form", ["table", "json", "csv"])
@pytest.mark.parametrize(
    "about, where", [("com", "the com"), ("origin", "the origin"), ("2,0,0", "the point [2.0, 0.0, 0.0]")]
)
def test_forward_dynamics_of_two_masses_on_a_line_exits_2_naming_the_point(tmp_path, about, where, form):
    """Two point masses on the x axis have I_xx = 0 about any point of that axis: no torque gives
    a finite angular acceleration. One line naming the file and the point, in every form."""
    spec = tmp_path / "rod.yaml"
    spec.write_text(
        "name: rod\nunits: {length: m, mass: kg}\nparts:\n"
        "  - {name: a, shape: point, mass: 1, position: [-1, 0, 0]}\n"
        "  - {name: b, shape: point, mass: 1, position: [1, 0, 0]}\n"
    )
    proc = run_rbi("dynamics", spec, "--torque", "0,0,1", "--about", about, "--format", form)
    assert proc.returncode == 2 and proc.stdout == ""
    assert proc.stderr == (
        f"rbi: {spec}: the inertia about {where} is singular: the body cannot be given an angular acceleration\n"
    )
