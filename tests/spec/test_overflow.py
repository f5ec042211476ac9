"""Issue 18, principle 5: numbers that overflow are errors, not zeros.

An axis or quaternion whose components are huge (or tiny) but finite is still a direction: the
part must be turned exactly as by the same direction written with small numbers. Inputs whose
results do not fit a double are exit 2 with one line (no pydantic URL, no LinAlgError, no
OverflowError). Each spec below is compared with the same spec written with unit-sized numbers
(an independent answer: the closed forms behind those are tested elsewhere).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rbi.core.rotation import (
    axis_angle_matrix,
    matrix_to_quaternion,
    quaternion_from_axis_angle,
    quaternion_to_matrix,
    unit_vector,
    vector_length,
)
from tests.conftest import one_line_exit_2, run_rbi_inprocess

# components from the smallest subnormal to the largest finite double
magnitudes = st.sampled_from(
    [5e-324, 1e-310, 1e-200, 1e-160, 1e154, 1.4e154, 1e200, 1e300, 1.7976931348623157e308]
)


@given(
    st.lists(st.sampled_from([-2.0, -1.0, 0.0, 0.5, 1.0, 3.0]), min_size=3, max_size=3).filter(
        lambda v: any(v)
    ),
    magnitudes,
)
@settings(max_examples=200, deadline=None)
def test_unit_vector_is_the_direction_at_any_scale(direction, scale):
    with np.errstate(over="ignore"):
        v = np.asarray(direction, dtype=float) * scale  # (subnormal scales round the components)
    if not any(v) or not np.all(np.isfinite(v)):
        return
    exact = np.ldexp(v, -math.frexp(float(np.max(np.abs(v))))[1])  # a power-of-two scaling is exact
    expected = exact / math.hypot(*exact)
    np.testing.assert_allclose(unit_vector(v), expected, rtol=0, atol=4e-16)


def test_unit_vector_refuses_zero_and_non_finite():
    for bad in ([0.0, 0.0, 0.0], [np.inf, 0.0, 0.0], [np.nan, 1.0, 0.0]):
        with pytest.raises(ValueError):
            unit_vector(bad)


def test_vector_length_is_finite_up_to_the_largest_double():
    assert vector_length([3e300, 4e300, 0.0]) == pytest.approx(5e300, rel=1e-15)
    assert vector_length([3e-320, 4e-320, 0.0]) == pytest.approx(5e-320, rel=1e-3)  # subnormal precision
    assert vector_length([1.7e308, 1.7e308, 0.0]) == np.inf  # the length itself does not fit


@pytest.mark.parametrize("scale", [1e-300, 1e155, 1e200, 1e308])
def test_rotations_from_huge_and_tiny_axes_and_quaternions(scale):
    axis = np.array([0.5, -1.0, 1.0])
    np.testing.assert_allclose(axis_angle_matrix(axis * scale, 0.7), axis_angle_matrix(axis, 0.7), atol=1e-15)
    np.testing.assert_allclose(
        quaternion_from_axis_angle(axis * scale, 0.7), quaternion_from_axis_angle(axis, 0.7), atol=1e-15
    )
    q = np.array([0.5, -0.5, 0.1, 0.7])
    np.testing.assert_allclose(quaternion_to_matrix(q * scale), quaternion_to_matrix(q), atol=1e-15)
    R = quaternion_to_matrix(q)
    np.testing.assert_allclose(matrix_to_quaternion(R), q / np.linalg.norm(q), atol=1e-15)


def _inertia(write_spec, text, name="body.yaml"):
    proc = run_rbi_inprocess("inertia", write_spec(text, name), "--format", "json")
    assert proc.returncode == 0, proc.stderr
    data = json.loads(proc.stdout)
    return np.array(data["inertia"]), np.array(data["center_of_mass"])


HUGE_SPECS = {
    "box rotation axis": (
        "- {{shape: box, mass: 1, size: [1, 2, 3], center: [0, 0, 0], "
        "rotation: {{axis: [{a}, 0, {a}], angle_deg: 90}}}}"
    ),
    "box quaternion": "- {{shape: box, mass: 1, size: [1, 2, 3], center: [0, 0, 0], rotation: {{quaternion: [{a}, {a}, 0, {a}]}}}}",
    "torus axis": "- {{shape: torus, mass: 1, major_radius: 1, minor_radius: 0.2, center: [0, 0, 0], axis: [{a}, 0, 0]}}",
    "hemisphere axis": "- {{shape: hemisphere, mass: 1, radius: 1, center: [0, 0, 0], axis: [0, {a}, {a}]}}",
    "pattern axis": (
        "- {{shape: box, mass: 1, size: [1, 1, 2], center: [0, 0, 0], "
        "pattern: {{count: 3, axis: [{a}, 0, 0], through: [0, 1, 0]}}}}"
    ),
    "custom rotation": (
        "- {{shape: custom, mass: 1, center_of_mass: [0, 0, 0], inertia: {{ixx: 1, iyy: 2, izz: 2.5}}, "
        "rotation: {{quaternion: [{a}, {a}, {a}, 0]}}}}"
    ),
}


@pytest.mark.parametrize("case", sorted(HUGE_SPECS))
@pytest.mark.parametrize("scale", ["1e200", "1e-200", "1.5e308"])
def test_huge_and_tiny_directions_turn_the_part_as_unit_ones(write_spec, case, scale):
    template = "parts:\n  " + HUGE_SPECS[case] + "\n"
    expected, expected_com = _inertia(write_spec, template.format(a="1"), "unit.yaml")
    got, com = _inertia(write_spec, template.format(a=scale))
    np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(com, expected_com, rtol=1e-12, atol=1e-14)


@pytest.mark.parametrize(
    "text, words",
    [
        ("- {shape: sphere, density: 1000, radius: 1.0e+200, center: [0, 0, 0]}", ("parts[0]", "too large")),
        (  # R⁴ = 1e320 leaves a double inside the thick shell's closed form
            "- {shape: spherical_shell, mass: 1, outer_radius: 1.0e+80, inner_radius: 1.0e+79, center: [0, 0, 0]}",
            ("parts[0]", "too large"),
        ),
        (
            "- {shape: hemisphere, density: 1, radius: 1.0e+110, center: [0, 0, 0], axis: [0, 0, 1]}",
            ("parts[0]", "too large"),
        ),
        (
            "- {shape: custom, mass: 1, center_of_mass: [0, 0, 0], inertia: {ixx: 1.0e+308, iyy: 1.0e+308, izz: 1.0e+308}}",
            ("parts[0]", "too large"),
        ),
        (
            "- {shape: custom, mass: 1, center_of_mass: [0, 0, 0], inertia: {ixx: 1, iyy: 1, izz: 1}, about: [1.0e+200, 0, 0]}",
            ("parts[0]", "too large"),
        ),
        (
            "- {shape: box, density: 1.0e+300, size: [1.0e+10, 1.0e+10, 1.0e+10], center: [0, 0, 0]}",
            ("parts[0]", "too large"),
        ),
    ],
)
def test_overflowing_parts_are_one_line_exit_2(write_spec, text, words):
    proc = run_rbi_inprocess("inertia", write_spec("parts:\n  " + text + "\n"))
    one_line_exit_2(proc, *words)
    assert (
        "pydantic" not in proc.stderr and "Error:" not in proc.stderr and "internal error" not in proc.stderr
    )


URDF = """<robot name="r"><link name="l"><inertial><origin xyz="0 0 0" rpy="{rpy}"/><mass value="1"/>
<inertia ixx="{i}" iyy="{i}" izz="{i}" ixy="0" ixz="0" iyz="0"/></inertial></link></robot>
"""


@pytest.mark.parametrize("rpy, inertia", [("1e307 0 0", "1"), ("0 0 0", "1e308"), ("0 0 0", "1.7e308")])
@pytest.mark.parametrize("command", [("import",), ("import", "--format", "json"), ("validate",)])
def test_robot_file_overflow_is_exit_2(tmp_path, rpy, inertia, command):
    path = tmp_path / "r.urdf"
    path.write_text(URDF.format(rpy=rpy, i=inertia))
    proc = run_rbi_inprocess(*command, path)
    one_line_exit_2(proc)
    assert "Error" not in proc.stderr.split(":", 1)[0] and "internal error" not in proc.stderr


@pytest.mark.parametrize(
    "args, words",
    [
        (["--seed", "-1"], ("--seed",)),
        (["--vary", "parts.bolt.position[0]=uniform(-1e308,1e308)"], ("--vary", "uniform")),
        (["--vary", "parts.bolt.mass=normal(1,1e308)"], ()),
    ],
)
def test_sweep_draws_that_overflow_are_exit_2(bodies, args, words):
    base = ["sweep", bodies / "top_bolted.yaml", "--mass-properties", "--runs", "3"]
    if "--seed" in args:
        base += ["--vary", "parts.bolt.mass=uniform(0.01,0.02)"]
    proc = run_rbi_inprocess(*base, *args)
    one_line_exit_2(proc, *words)


# --- cases found while hunting (hypothesis over huge and tiny finite numbers for each shape) ---


def test_frustum_with_tiny_radii_is_a_thin_cylinder(write_spec):
    """Found: radii near 1e-160 made a² + ab + b² underflow to 0 and the frustum divided by
    zero (internal error, exit 1). Equal radii are a cylinder: axial ½ m r², transverse
    m (3r² + h²)/12."""
    inertia, com = _inertia(
        write_spec,
        "parts:\n  - {shape: frustum, mass: 2, start_radius: 1.0e-160, "
        "end_radius: 1.0e-160, start: [0, 0, 0], end: [0, 0, 3]}\n",
    )
    np.testing.assert_allclose(
        np.diag(inertia), [2 * 9 / 12, 2 * 9 / 12, 0.5 * 2 * 1e-320], rtol=1e-3, atol=0
    )
    np.testing.assert_allclose(com, [0, 0, 1.5])


def test_subnormal_density_is_refused_not_printed_as_inf(write_spec):
    """Found: a table scaled by 10**-324 (= 0) printed inf and nan for an inertia of 1e-323.
    A subnormal density is now refused (tests/spec/test_subnormal.py): its moments have lost
    their digits."""
    proc = run_rbi_inprocess(
        "inertia",
        write_spec("parts:\n  - {shape: sphere, density: 5.0e-324, radius: 1, center: [0, 0, 0]}\n"),
    )
    one_line_exit_2(proc, "density: 5e-324 is subnormal")
    assert "inf" not in proc.stdout and "nan" not in proc.stdout, proc.stdout


SHAPE_TEMPLATES = {
    "point": "{{shape: point, mass: {m}, position: [{p}, 0, 0]}}",
    "sphere": "{{shape: sphere, {md}, radius: {r}, center: [{p}, 0, 0]}}",
    "shell": "{{shape: shell, {md}, outer_radius: {r}, inner_radius: {s}, center: [0, 0, {p}]}}",
    "box": "{{shape: box, {md}, size: [{r}, {r}, {s}], center: [0, {p}, 0], rotation: {{axis: [{p}, 1, 0], angle_deg: 30}}}}",
    "cylinder": "{{shape: cylinder, {md}, radius: {r}, start: [0, 0, {p}], end: [{s}, 0, 0]}}",
    "cone": "{{shape: cone, {md}, radius: {r}, apex: [0, 0, {p}], base: [{s}, 0, 0]}}",
    "tube": "{{shape: tube, {md}, outer_radius: {r}, inner_radius: {s}, start: [0, 0, {p}], end: [1, 0, 0]}}",
    "frustum": "{{shape: frustum, {md}, start_radius: {r}, end_radius: {s}, start: [0, 0, {p}], end: [1, 0, 0]}}",
    "ellipsoid": "{{shape: ellipsoid, {md}, semi_axes: [{r}, {s}, 1], center: [0, 0, {p}]}}",
    "rod": "{{shape: rod, mass: {m}, start: [0, 0, {p}], end: [{r}, 0, 0]}}",
    "torus": "{{shape: torus, {md}, major_radius: {r}, minor_radius: {s}, center: [{p}, 0, 0], axis: [{p}, 1, 0]}}",
    "hemisphere": "{{shape: hemisphere, {md}, radius: {r}, center: [{p}, 0, 0], axis: [{p}, 1, 0]}}",
    "capsule": "{{shape: capsule, {md}, radius: {r}, start: [0, 0, {p}], end: [{s}, 0, 0]}}",
    "custom": "{{shape: custom, mass: {m}, center_of_mass: [{p}, 0, 0], inertia: {{ixx: {r}, iyy: {r}, izz: {s}}}}}",
}
extreme = st.sampled_from(
    ["5.0e-324", "1.0e-300", "1.0e-160", "1", "1.0e+154", "1.0e+160", "1.0e+200", "1.0e+300", "1.7e+308"]
)


@given(
    st.sampled_from(sorted(SHAPE_TEMPLATES)),
    extreme,
    extreme,
    extreme,
    extreme,
    st.booleans(),
    st.sampled_from(["inertia", "principal", "check"]),
)
@settings(max_examples=120, deadline=None)
def test_any_finite_numbers_give_an_answer_or_one_line_exit_2(
    tmp_path_factory, shape, m, p, r, s, by_density, command
):
    md = f"density: {m}" if by_density else f"mass: {m}"
    text = "parts:\n  - " + SHAPE_TEMPLATES[shape].format(m=m, p=p, r=r, s=s, md=md) + "\n"
    path = tmp_path_factory.mktemp("spec") / "body.yaml"
    path.write_text(text)
    proc = run_rbi_inprocess(command, path, "--format", "json")
    assert proc.returncode in (0, 1, 2), (text, proc.stderr)
    assert "internal error" not in proc.stderr and "Traceback" not in proc.stderr, (text, proc.stderr)
    if proc.returncode == 2:
        one_line_exit_2(proc)
    else:
        assert "NaN" not in proc.stdout and "Infinity" not in proc.stdout, (text, proc.stdout)


def test_mjcf_quaternion_of_any_size_turns_the_inertial_frame(tmp_path):
    """MJCF quats are normalised by the same core helper: [1e200, 0, 0, 1e200] is a quarter
    turn about z, exactly as [1, 0, 0, 1]."""
    results = []
    for quat in ("1 0 0 1", "1e200 0 0 1e200", "1e-200 0 0 1e-200"):
        path = tmp_path / "robot.xml"
        path.write_text(
            f'<mujoco><worldbody><body name="b"><inertial pos="0 0 0" quat="{quat}" mass="1" '
            f'diaginertia="1 2 3"/></body></worldbody></mujoco>'
        )
        proc = run_rbi_inprocess("import", path, "--format", "json")
        assert proc.returncode == 0, proc.stderr
        results.append(np.array(json.loads(proc.stdout)["links"][0]["inertia"]))
    np.testing.assert_allclose(
        results[0], np.diag([2.0, 1.0, 3.0]), atol=1e-15
    )  # x and y swapped by the turn
    for other in results[1:]:
        np.testing.assert_allclose(other, results[0], atol=1e-15)


@pytest.mark.parametrize(
    "text",
    [
        "- {shape: cylinder, mass: 1.0e-300, radius: 1.0e-160, start: [0, 0, 0], end: [0, 0, 2.0e-160]}",
        "- {shape: sphere, mass: 1.0e-200, radius: 1.0e-60, center: [0, 0, 0]}",
        "- {shape: box, mass: 1.0e-250, size: [1.0e-40, 1.0e-40, 1.0e-40], center: [0, 0, 0]}",
    ],
)
@pytest.mark.parametrize("copies", [1, 40])  # 40: the batched path for many parts
def test_a_solid_whose_moments_underflow_is_refused_not_printed_as_zero(write_spec, text, copies):
    """Found: a cylinder of mass 1e-300 and radius 1e-160 printed an inertia of exactly zero
    (the true moments, about 1e-620, are below the smallest double): a solid with size and
    mass has moments; zeros would be a wrong answer. One line naming the part, exit 2."""
    proc = run_rbi_inprocess(
        "inertia", write_spec("parts:\n" + ("  " + text + "\n") * copies), "--format", "json"
    )
    one_line_exit_2(proc, "parts[0]", "too small")


def test_point_masses_keep_their_zero_moments(write_spec):
    """A point mass has no moments about its own centre: not an underflow. Two of 1e-300 kg at
    ±1 m: I_yy = I_zz = 2e-300 kg·m², I_xx = 0."""
    proc = run_rbi_inprocess(
        "inertia",
        write_spec(
            "parts:\n  - {shape: point, mass: 1.0e-300, position: [1, 0, 0]}\n"
            "  - {shape: point, mass: 1.0e-300, position: [-1, 0, 0]}\n"
        ),
        "--format",
        "json",
    )
    assert proc.returncode == 0, proc.stderr
    np.testing.assert_allclose(np.diag(json.loads(proc.stdout)["inertia"]), [0, 2e-300, 2e-300], rtol=1e-15)


@pytest.mark.parametrize(
    "command", [["simulate", "--spin", "10"], ["animate", "--spin", "10", "--out", "a.html"]]
)
def test_a_pivot_so_far_its_inertia_overflows_says_so(write_spec, tmp_path, command):
    """`rbi simulate` of a top whose pivot is at 1e308 m printed numpy's words 'pivot: cannot
    simulate: Eigenvalues did not converge'; the inertia about that pivot overflows, which is what
    the message now says (and the sweep's status alike)."""
    spec = write_spec(
        "pivot: [1.0e+308, 0, 0]\nparts:\n  - {shape: cylinder, mass: 1, radius: 0.1, start: [0, 0, 0], end: [0, 0, 1]}\n"
    )
    args = [a if a != "a.html" else str(tmp_path / "a.html") for a in command]
    proc = run_rbi_inprocess(command[0], spec, *args[1:], "--duration", "0.01")
    one_line_exit_2(proc, "pivot: cannot simulate", "inertia about the pivot", "too large")
    assert "Eigenvalues" not in proc.stderr and not (tmp_path / "a.html").exists()
    sweep = run_rbi_inprocess("sweep", spec, "--spin", "10", "--duration", "0.01", "--format", "json")
    assert sweep.returncode == 0, sweep.stderr
    status = json.loads(sweep.stdout)["runs"][0]["status"]
    assert "inertia about the pivot" in status and "too large" in status and "Eigenvalues" not in status


def test_a_sphere_whose_volume_overflows_has_an_inertia_but_no_parts_table(write_spec):
    """Found: a sphere of radius 1e110 m and mass 1 kg was an internal error (exit 1) in every
    command: Python's float power (r³ = 1e330) raises OverflowError where numpy gives inf. Its
    inertia, 2/5 m r² = 4e219 kg·m², is a result; its volume is not a double, so ``rbi parts``
    refuses it in one line (JSON cannot hold inf) in every output form."""
    spec = write_spec("parts:\n  - {shape: sphere, mass: 1, radius: 1.0e110, center: [0, 0, 0]}\n")
    proc = run_rbi_inprocess("inertia", spec, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    np.testing.assert_allclose(np.diag(json.loads(proc.stdout)["inertia"]), [4e219] * 3, rtol=1e-15)
    for fmt in ("table", "json", "csv"):
        one_line_exit_2(run_rbi_inprocess("parts", spec, "--format", fmt), "volume", "not finite")


def test_holes_in_a_body_whose_masses_underflow_are_one_line(write_spec):
    """Found: a disc with a hole, both 1e-110 m across at density 1, has masses that underflow
    to 0; the holes check summed a massless body and stopped with an internal error (exit 1).
    It is refused as any massless body is."""
    spec = write_spec(
        "parts:\n"
        "  - {shape: cylinder, density: 1, radius: 1.0e-110, start: [0, 0, 0], end: [0, 0, 1.0e-111]}\n"
        "  - {shape: cylinder, density: 1, radius: 1.0e-111, start: [0, 0, 0], end: [0, 0, 1.0e-111],"
        " subtract: true}\n"
    )
    one_line_exit_2(run_rbi_inprocess("inertia", spec), "mass")


def test_a_part_too_thin_for_any_units_guess_is_still_read(write_spec):
    """Found: a cone 0.04 long across but 6e-162 high (volume 1e-165) made the units guess
    take log10 of a probability that underflowed to 0: an internal error (exit 1). The part is
    read: its mass is density × π r² h / 3."""
    spec = write_spec(
        "parts:\n  - {shape: cone, density: 1, radius: 0.04, apex: [0, 0, 0], base: [0, 0, 6.0e-162]}\n"
    )
    proc = run_rbi_inprocess("inertia", spec, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    assert "internal error" not in proc.stderr
    assert json.loads(proc.stdout)["mass"] == pytest.approx(math.pi * 0.04**2 * 6.0e-162 / 3, rel=1e-12)


def test_an_uncertainty_whose_squares_overflow_is_still_its_root_sum_square(write_spec):
    """Found: a cone of mass 1 kg, radius 1e110 ± 1e108 m: the inertia is 3e219 kg·m² and its
    uncertainty (∂I/∂r · u(r): 3/10 m r u = 3e217 about x and y, 3/5 m r u = 6e217 about z)
    squared past a double, so JSON output was an internal error (exit 1)."""
    spec = write_spec(
        'parts:\n  - {shape: cone, mass: 1, radius: "1e110 ± 1e108", apex: [0, 0, 0], base: [0, 0, 1]}\n'
    )
    proc = run_rbi_inprocess("inertia", spec, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    spread = np.diag(json.loads(proc.stdout)["uncertainty"]["inertia"])
    np.testing.assert_allclose(spread, [3e217, 3e217, 6e217], rtol=1e-12)


def test_a_monte_carlo_spread_whose_squares_overflow_is_still_its_standard_deviation(write_spec):
    """The same cone by Monte Carlo: the draws' standard deviation squared deviations of 1e217
    past a double, so the JSON was an internal error (exit 1). 2,000 draws put it within a few
    per cent of the linear 3e217 and 6e217 kg·m² (the inertia is linear in r² and u(r) is 1%)."""
    spec = write_spec(
        'parts:\n  - {shape: cone, mass: 1, radius: "1e110 ± 1e108", apex: [0, 0, 0], base: [0, 0, 1]}\n'
    )
    proc = run_rbi_inprocess(
        "uncertainty", spec, "--method", "monte-carlo", "--samples", "2000", "--seed", "1", "--format", "json"
    )
    assert proc.returncode == 0, proc.stderr
    u = {q["quantity"]: q["u"] for q in json.loads(proc.stdout)["quantities"]}
    np.testing.assert_allclose([u["inertia[0][0]"], u["inertia[2][2]"]], [3e217, 6e217], rtol=0.1)


@pytest.mark.parametrize("copies", [1, 40])  # 40: the batched path for many parts
def test_a_pattern_of_massless_copies_is_refused_naming_the_part(write_spec, copies):
    """Found: a patterned cylinder 1e-110 m across at density 1 has copies whose mass underflows
    to 0; combining the pattern raised inside the batched builder, an internal error (exit 1).
    One line naming the part, exit 2."""
    spec = write_spec(
        "parts:\n  - {shape: box, mass: 1, size: [1, 1, 1], center: [0, 0, 0]}\n"
        + "  - {shape: cylinder, density: 1, radius: 1.0e-110, start: [1, 0, 0], end: [1, 0, 1.0e-110],"
        " pattern: {count: 6, axis: [0, 0, 1], through: [0, 0, 0]}}\n" * copies
    )
    one_line_exit_2(run_rbi_inprocess("inertia", spec), "parts[1]", "mass")


def test_monte_carlo_draws_that_overflow_are_one_line(write_spec):
    """Found: a point at x = 0 ± 1e300 m drawn by Monte Carlo gives x² = inf in the inertia, and
    the principal moments of that (numpy's eigvalsh) were an internal error (LinAlgError, exit
    1). The linear method answers (its sensitivities are finite); Monte Carlo refuses in one line
    in every output form."""
    spec = write_spec(
        "parts:\n  - {shape: point, mass: 1, position: ['0 ± 1e300', 0, 0]}\n"
        "  - {shape: point, mass: 1, position: [1, 0, 0]}\n"
    )
    assert run_rbi_inprocess("uncertainty", spec, "--format", "json").returncode == 0
    for fmt in ("table", "json", "csv"):
        proc = run_rbi_inprocess(
            "uncertainty", spec, "--method", "monte-carlo", "--samples", "100", "-f", fmt
        )
        one_line_exit_2(proc, "Monte Carlo", "not finite")
