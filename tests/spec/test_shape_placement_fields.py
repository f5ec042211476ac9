"""The added shapes as written in YAML: placement fields, the rotation form, custom parts and
their error messages (file: part: field: what is wrong)."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from rbi.spec.errors import InputError
from rbi.spec.load import load_body


def body(write_spec, parts: str, header: str = ""):
    return load_body(
        write_spec(textwrap.dedent(header) + "parts:\n" + textwrap.indent(textwrap.dedent(parts), "  "))
    )


def error(write_spec, parts: str, header: str = "") -> str:
    with pytest.raises(InputError) as info:
        body(write_spec, parts, header)
    return str(info.value)


def test_box_turned_a_quarter_turn_swaps_moments_exactly(write_spec):
    b = body(
        write_spec,
        """
        - shape: box
          mass: 12
          center: [0, 0, 0]
          size: [1, 2, 3]
          rotation: {axis: [0, 0, 1], angle_deg: 90}
    """,
    )
    # Edges along x, y, z become y, x, z: Ixx = m (a² + c²)/12 with a = 1 now along y.
    np.testing.assert_array_equal(b.props.inertia_about_com, np.diag([10.0, 13.0, 5.0]))


def test_rotation_form_matches_scipy_axis_angle(write_spec):
    b = body(
        write_spec,
        """
        - shape: ellipsoid
          mass: 5
          center: [1, 2, 3]
          semi_axes: [0.3, 0.2, 0.1]
          rotation: {axis: [1, 2, 2], angle_deg: 40}
    """,
    )
    R = Rotation.from_rotvec(np.radians(40) * np.array([1, 2, 2]) / 3).as_matrix()
    own = 5 / 5 * np.diag([0.2**2 + 0.1**2, 0.3**2 + 0.1**2, 0.3**2 + 0.2**2])
    np.testing.assert_allclose(b.props.inertia_about_com, R @ own @ R.T, rtol=1e-13, atol=1e-16)
    np.testing.assert_array_equal(b.props.center_of_mass, [1, 2, 3])


def test_density_times_closed_form_volume_for_each_solid(write_spec):
    b = body(
        write_spec,
        """
        - {shape: sphere, density: 2, center: [0, 0, 0], radius: 1}
        - {shape: spherical_shell, density: 2, center: [0, 0, 0], outer_radius: 2, inner_radius: 1}
        - {shape: tube, density: 2, start: [0, 0, 0], end: [0, 0, 3], outer_radius: 2, inner_radius: 1}
        - {shape: frustum, density: 2, start: [0, 0, 0], end: [0, 0, 3], start_radius: 1, end_radius: 2}
        - {shape: box, density: 2, center: [0, 0, 0], size: [1, 2, 3]}
        - {shape: ellipsoid, density: 2, center: [0, 0, 0], semi_axes: [1, 2, 3]}
    """,
    )
    pi = np.pi
    volumes = [4 / 3 * pi, 4 / 3 * pi * 7, pi * 3 * 3, pi * 3 * 7 / 3, 6.0, 4 / 3 * pi * 6]
    np.testing.assert_allclose([e.mass for e in b.elements], 2 * np.array(volumes), rtol=1e-14)


def test_thin_shell_and_thin_tube_take_mass(write_spec):
    b = body(
        write_spec,
        """
        - {shape: spherical_shell, mass: 3, center: [0, 0, 0], outer_radius: 2, inner_radius: 2}
        - {shape: tube, mass: 3, start: [0, 0, -1], end: [0, 0, 1], outer_radius: 2, inner_radius: 2}
    """,
    )
    np.testing.assert_allclose(b.elements[0].inertia_about_com, 2 / 3 * 3 * 4 * np.eye(3), rtol=1e-15)
    assert b.elements[1].inertia_about_com[2, 2] == pytest.approx(3 * 4, rel=1e-15)  # hoop: m R²


def test_rod_is_a_line_mass(write_spec):
    b = body(write_spec, "- {shape: rod, mass: 3, start: [0, 0, 0], end: [2, 0, 0]}\n")
    np.testing.assert_allclose(b.props.inertia_about_com, np.diag([0.0, 1.0, 1.0]), atol=1e-15)


def test_custom_about_another_point_is_moved_to_the_com(write_spec):
    # A 2 kg point-like part at (1, 0, 0) with Izz = 5 about the origin has Izz = 5 - 2·1² = 3
    # about its own centre of mass; Ixx is unchanged (the offset is along x).
    b = body(
        write_spec,
        """
        - shape: custom
          mass: 2
          center_of_mass: [1, 0, 0]
          about: [0, 0, 0]
          inertia: {ixx: 2, iyy: 5, izz: 5}
    """,
    )
    np.testing.assert_allclose(b.props.inertia_about_com, np.diag([2.0, 3.0, 3.0]), rtol=1e-15)


def test_custom_matrix_and_component_forms_agree_and_are_turned(write_spec):
    matrix = body(
        write_spec,
        """
        - shape: custom
          mass: 1
          center_of_mass: [0, 0, 0]
          inertia: [[2, -0.1, 0], [-0.1, 3, 0.2], [0, 0.2, 4]]
          rotation: {axis: [1, 0, 0], angle_deg: 30}
    """,
    )
    components = body(
        write_spec,
        """
        - shape: custom
          mass: 1
          center_of_mass: [0, 0, 0]
          inertia: {ixx: 2, iyy: 3, izz: 4, ixy: -0.1, iyz: 0.2}
          rotation: {axis: [1, 0, 0], angle_deg: 30}
    """,
    )
    R = Rotation.from_euler("x", 30, degrees=True).as_matrix()
    given = np.array([[2, -0.1, 0], [-0.1, 3, 0.2], [0, 0.2, 4]])
    np.testing.assert_allclose(matrix.props.inertia_about_com, R @ given @ R.T, rtol=1e-14, atol=1e-16)
    np.testing.assert_array_equal(matrix.props.inertia_about_com, components.props.inertia_about_com)


@pytest.mark.parametrize(
    "inertia, words",
    [
        ("{ixx: 1, iyy: 1, izz: 2.1}", "triangle inequality I1 + I2 >= I3"),
        ("{ixx: -1, iyy: 2, izz: 2}", "not positive definite"),
        ("[[1, 0.1, 0], [0, 1, 0], [0, 0, 1]]", "not symmetric"),
    ],
)
def test_custom_inertia_must_be_physical(write_spec, inertia, words):
    message = error(
        write_spec,
        f"- {{name: sensor, shape: custom, mass: 0.01, center_of_mass: [0, 0, 0], inertia: {inertia}}}\n",
    )
    assert "body.yaml: parts[0] (sensor): inertia: " in message
    assert words in message


def test_custom_tiny_si_inertia_is_judged_relatively(write_spec):
    ok = "- {shape: custom, mass: 1e-4, center_of_mass: [0, 0, 0], inertia: {ixx: 1e-10, iyy: 1e-10, izz: 2e-10}}\n"
    assert body(write_spec, ok).props.mass == 1e-4
    bad = ok.replace("izz: 2e-10", "izz: 2.0001e-10")
    assert "triangle inequality" in error(write_spec, bad)


def test_custom_about_point_too_far_for_the_given_inertia(write_spec):
    message = error(
        write_spec,
        "- {name: imu, shape: custom, mass: 2, center_of_mass: [1, 0, 0], about: [0, 0, 0],"
        " inertia: {ixx: 1, iyy: 1, izz: 1}}\n",
    )
    assert "parts[0] (imu): inertia:" in message and "about the centre of mass" in message


@pytest.mark.parametrize(
    "part, expected",
    [
        (
            "{name: p, shape: box, mass: 1, center: [0, 0, 0], size: [1, -2, 3]}",
            "parts[0] (p): size[1]: must be greater than 0",
        ),
        (
            "{name: p, shape: box, mass: 1, center: [0, 0, 0], size: [1, 2, 3], rotation: {axis: [0, 0, 0], angle_deg: 5}}",
            "parts[0] (p): rotation: axis: must not be the zero vector",
        ),
        (
            "{name: p, shape: box, mass: 1, center: [0, 0, 0], size: [1, 2, 3], rotation: {axis: [0, 0, 1], angle: 5}}",
            "parts[0] (p): rotation.angle: unknown field",
        ),
        (
            "{name: p, shape: tube, mass: 1, start: [0, 0, 0], end: [0, 0, 1], outer_radius: 1, inner_radius: 2}",
            "parts[0] (p): inner_radius: must not exceed outer_radius",
        ),
        (
            "{name: p, shape: tube, density: 1, start: [0, 0, 0], end: [0, 0, 1], outer_radius: 1, inner_radius: 1}",
            "parts[0] (p): density: a thin-walled tube (inner_radius = outer_radius) has no volume",
        ),
        (
            "{name: p, shape: spherical_shell, mass: 1, center: [0, 0, 0], outer_radius: 1, inner_radius: -0.5}",
            "parts[0] (p): inner_radius: must not be negative",
        ),
        (
            "{name: p, shape: frustum, mass: 1, start: [0, 0, 0], end: [0, 0, 1], start_radius: 0, end_radius: 0}",
            "parts[0] (p): start_radius, end_radius: at least one must be greater than 0",
        ),
        (
            "{name: p, shape: rod, density: 1, start: [0, 0, 0], end: [0, 0, 1]}",
            "parts[0] (p): density: a thin rod takes `mass` only",
        ),
        (
            "{name: p, shape: point, mass: 1, position: [0, 0, 0], subtract: true}",
            "parts[0] (p): subtract: only solids with a volume can be subtracted",
        ),
        (
            "{name: p, shape: custom, mass: 1, center_of_mass: [0, 0, 0], inertia: {ixx: 1, iyy: 1}}",
            "parts[0] (p): inertia: izz: missing required component",
        ),
        (
            "{name: p, shape: custom, mass: 1, center_of_mass: [0, 0, 0], inertia: [[1, 0], [0, 1]]}",
            "parts[0] (p): inertia: must be a 3×3 matrix",
        ),
        (
            "{name: p, shape: sphere, mass: 1, center: [0, 0, 0], radius: 1, subtract: yes please}",
            "parts[0] (p): subtract: ",
        ),
    ],
)
def test_field_errors_name_part_and_field(write_spec, part, expected):
    message = error(write_spec, f"- {part}\n")
    assert expected in message, message
    assert "Traceback" not in message and "\n" not in message


ELLIPSOID = (
    "- {{shape: ellipsoid, mass: 5, center: [1, 2, 3], semi_axes: [0.3, 0.2, 0.1], rotation: {rotation}}}\n"
)


def _own_ellipsoid_inertia():
    return np.diag([0.2**2 + 0.1**2, 0.3**2 + 0.1**2, 0.3**2 + 0.2**2])


@pytest.mark.parametrize("sequence", ["xyz", "zyx", "zxz", "XYZ", "ZYX", "ZXZ", "yxy"])
def test_euler_form_matches_scipy_from_euler(write_spec, sequence):
    angles = [25.0, -40.0, 70.0]
    b = body(write_spec, ELLIPSOID.format(rotation=f"{{euler_deg: {angles}, sequence: {sequence}}}"))
    R = Rotation.from_euler(sequence, angles, degrees=True).as_matrix()
    np.testing.assert_allclose(
        b.props.inertia_about_com, R @ _own_ellipsoid_inertia() @ R.T, rtol=1e-13, atol=1e-15
    )


def test_quaternion_form_matches_scipy_and_is_normalised(write_spec):
    q_wxyz = np.array([0.9, 0.1, -0.3, 0.2])
    b = body(write_spec, ELLIPSOID.format(rotation=f"{{quaternion: {(3 * q_wxyz).tolist()}}}"))
    R = Rotation.from_quat(np.r_[q_wxyz[1:], q_wxyz[0]]).as_matrix()  # scipy is scalar-last
    np.testing.assert_allclose(
        b.props.inertia_about_com, R @ _own_ellipsoid_inertia() @ R.T, rtol=1e-13, atol=1e-15
    )


def test_one_rotation_written_three_ways_gives_bit_close_inertia(write_spec):
    # A quarter turn about z: axis-angle, quaternion [cos 45°, 0, 0, sin 45°], Euler z=90°.
    forms = [
        "{axis: [0, 0, 1], angle_deg: 90}",
        f"{{quaternion: [{float(np.cos(np.pi / 4))!r}, 0, 0, {float(np.sin(np.pi / 4))!r}]}}",
        "{euler_deg: [90, 0, 0], sequence: zyx}",
        "{euler_deg: [0, 0, 90], sequence: XYZ}",
    ]
    results = [body(write_spec, ELLIPSOID.format(rotation=form)).props.inertia_about_com for form in forms]
    for other in results[1:]:
        np.testing.assert_allclose(other, results[0], rtol=0, atol=1e-15)
    np.testing.assert_allclose(
        results[0], 5 / 5 * np.diag([0.3**2 + 0.1**2, 0.2**2 + 0.1**2, 0.3**2 + 0.2**2]), rtol=1e-15
    )


@pytest.mark.parametrize(
    "rotation, expected",
    [
        ("{quaternion: [0, 0, 0, 0]}", "rotation: quaternion: must not be zero"),
        ("{quaternion: [1, 0, 0]}", "rotation.quaternion:"),
        ("{euler_deg: [1, 2, 3]}", "rotation: euler_deg, sequence: give both"),
        ("{euler_deg: [1, 2, 3], sequence: xYz}", "rotation.sequence:"),
        ("{euler_deg: [1, 2, 3], sequence: xwz}", "rotation.sequence:"),
        ("{axis: [0, 0, 1], angle_deg: 9, quaternion: [1, 0, 0, 0]}", "give exactly one form"),
        ("{axis: [0, 0, 1]}", "rotation: axis, angle_deg: give both"),
        ("{}", "give exactly one form"),
    ],
)
def test_rotation_form_errors_name_the_field(write_spec, rotation, expected):
    message = error(write_spec, ELLIPSOID.format(rotation=rotation))
    assert "parts[0]" in message and expected in message, message
    assert "\n" not in message
