"""A large robot file audited with its costly numbers in bulk (issue 25): each shortcut gives
bit for bit what the general computation gives, the bulk audit flags exactly what the one-link
audit flags, and a long chain is read in one pass (no walk to the root per link)."""

from __future__ import annotations

import sys

import numpy as np
import pytest

from rbi.core.mass import MassProperties
from rbi.errors import InputError

RNG = np.random.default_rng(25)


def _symmetric(i: int) -> np.ndarray:
    """A random symmetric matrix; every other one diagonal, some with -0.0 entries."""
    A = RNG.normal(size=(3, 3)) * 10.0 ** RNG.integers(-12, 12)
    A = 0.5 * (A + A.T)
    if i % 2:
        A = np.where(np.eye(3, dtype=bool), A, -0.0 if i % 4 == 1 else 0.0)
    if i % 8 == 3:
        A[1, 1] = A[0, 0]
    return A


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    return np.asarray(a).tobytes() == np.asarray(b).tobytes()


def test_moments_without_axes_are_the_principal_moments_bit_for_bit():
    from rbi.robot.audit import _stack_moments

    for i in range(3000):
        properties = MassProperties(1.0, np.zeros(3), _symmetric(i))
        assert _same(
            np.array(_stack_moments(properties.inertia_about_com[None])[0]), properties.moments + 0.0
        )


def test_the_dot_products_are_numpys_bit_for_bit():
    from rbi.robot.tree import dot_rows as _dot

    a = RNG.normal(size=(3000, 3)) * 10.0 ** RNG.integers(-8, 8, size=(3000, 1))
    g = RNG.normal(size=3)
    a[::3, 1] = 0.0
    dotted = _dot(a, g)
    for i in range(len(a)):
        assert _same(dotted[i], g @ a[i])


def test_the_placement_on_stacks_is_the_pose_by_pose_one_bit_for_bit():
    """Poses composed one tree level at a time on (n, 3, 3) stacks equal :class:`Pose` products
    link by link (numpy's matmul makes the same BLAS call per matrix of a stack)."""
    from rbi.formats.robot import Pose
    from rbi.robot.tree import stack_apply

    R = RNG.normal(size=(2000, 3, 3))
    inner = RNG.normal(size=(2000, 3, 3))
    t = RNG.normal(size=(2000, 3)) * 10.0 ** RNG.integers(-6, 6, size=(2000, 1))
    u = RNG.normal(size=(2000, 3))
    turned, moved = np.matmul(R, inner), stack_apply(R, u) + t
    for i in range(len(R)):
        one = Pose(R[i], t[i]).then(Pose(inner[i], u[i]))
        assert _same(turned[i], one.rotation) and _same(moved[i], one.translation)


_SHAPES = (
    '<box size="0.2 0.1 0.05"/>',
    '<cylinder radius="0.03" length="0.2"/>',
    '<sphere radius="0.05"/>',
    '<capsule radius="0.02" length="0.1"/>',
    '<box size="0 0.1 0.05"/>',  # no volume: no geometry
)


def _urdf(links: list[tuple[float, np.ndarray]], chain: bool = False, shapes: bool = False) -> str:
    """A URDF whose link i has mass ``m`` and inertia ``I`` (any numbers, unphysical included)
    and a box (``shapes``: each primitive in turn, turned and moved off the link origin, some
    links with a second piece); joints make a chain or a binary tree."""
    parts = ['<robot name="r">']
    for i, (m, I) in enumerate(links):
        geometry = '<collision><geometry><box size="0.2 0.1 0.05"/></geometry></collision>'
        if shapes:
            origin = f'<origin xyz="{0.01 * i!r} -0.02 0.3" rpy="{0.1 * i!r} 0.2 -0.7"/>'
            geometry = f"<collision>{origin}<geometry>{_SHAPES[i % 5]}</geometry></collision>"
            geometry += geometry if i % 7 == 3 else ""
        parts.append(
            f'<link name="l{i}"><inertial><mass value="{m!r}"/><inertia ixx="{float(I[0, 0])!r}" ixy="{float(I[0, 1])!r}" '
            f'ixz="{float(I[0, 2])!r}" iyy="{float(I[1, 1])!r}" iyz="{float(I[1, 2])!r}" izz="{float(I[2, 2])!r}"/></inertial>'
            f"{geometry}</link>"
        )
    for i in range(1, len(links)):
        parent = i - 1 if chain else (i - 1) // 2
        parts.append(
            f'<joint name="j{i}" type="revolute"><parent link="l{parent}"/><child link="l{i}"/>'
            '<origin xyz="0.2 0 0" rpy="0.1 0 0.3"/><axis xyz="0 1 1"/><limit effort="1"/></joint>'
        )
    return "".join(parts) + "</robot>"


def _hostile_inertias(n: int) -> list[tuple[float, np.ndarray]]:
    """Physical inertias, placeholders (equal, round), negative moments, triangle breakers,
    rounding noise, asymmetric products, zero and negative masses."""
    box = np.diag([0.0010416666666666667, 0.0035416666666666665, 0.004166666666666667])
    found = []
    for i in range(n):
        kind = i % 9
        I = box * (10.0 ** RNG.uniform(-2, 2))
        if kind == 1:
            I = np.eye(3) * 0.1
        elif kind == 2:
            I = np.diag([1.0, 0.01, 0.001])
        elif kind == 3:
            I = np.diag([-1e-3, 2e-3, 2e-3])
        elif kind == 4:
            I = np.diag([1e-3, 1e-3, 3e-3])
        elif kind == 5:
            I = box.copy()
            I[0, 0] = -5.4e-20
        elif kind == 6:
            I = box + 1e-4 * _symmetric(2 * i)
        elif kind == 7:
            I = box * 1e3
        mass = [1.0, 0.0, -1.0, 0.53][i % 4] if kind == 8 else float(RNG.uniform(0.1, 10))
        found.append((mass, I))
    return found


@pytest.mark.parametrize(
    "chain, shapes, density, careful",
    [
        (False, False, None, False),
        (True, False, None, False),
        (False, True, None, False),
        (True, True, 500.0, False),
        (True, True, 500.0, True),
        (False, True, None, True),
    ],
)
def test_the_bulk_audit_flags_what_the_one_link_audit_flags(
    tmp_path, monkeypatch, chain, shapes, density, careful
):
    """Whichever form the audit reads the model in (``careful``: its links, made first and laid
    into the audit's arrays; else the reader's columns, as they are): each link's flags and
    numbers are those of the careful path, every geom measured one at a time and every link's
    pieces summed (none of it on the stacks of solid primitives, no link's only piece taken as
    it is)."""
    from rbi.formats import robot_xml
    from rbi.formats.robot_files import read_robot
    from rbi.formats.urdf import read_urdf
    from rbi.robot.audit import audit_model

    path = tmp_path / "r.urdf"
    path.write_text(_urdf(_hostile_inertias(200), chain=chain, shapes=shapes))
    model = read_urdf(robot_xml.read_xml(str(path))) if careful else read_robot(str(path))
    if careful:
        assert model.links  # made now: the audit reads the columns all the same
    bulk = audit_model(model, density=density)
    audit = sys.modules[audit_model.__module__]  # (rbi.robot.audit is also the name of a function)
    monkeypatch.setattr(audit, "SOLID_KINDS", ())  # no geom measured on the stacks
    monkeypatch.setattr(audit, "_alone", lambda n, rows, *args: np.zeros(len(rows), dtype=bool))
    one_by_one = audit_model(model, density=density)
    codes = set()
    for found, one in zip(bulk.links, one_by_one.links, strict=True):
        assert [f.as_dict() for f in found.flags] == [f.as_dict() for f in one.flags]
        assert _same(found.ratios, one.ratios) and found.com_offset == one.com_offset
        _assert_same_geometry(found, one)
        codes |= {f"{f.level} {f.code}" for f in found.flags}
    for name in ("com", "low", "high"):  # the centroid where the geometry has no mass, its bounds
        assert _same(getattr(bulk.audited, name), getattr(one_by_one.audited, name)), name
    assert {"error unphysical", "error placeholder", "warning mismatch", "error mismatch"} <= codes


def _assert_same_geometry(bulk, one) -> None:
    """The geometry the bulk audit measured is, bit for bit, what the one-link audit measures."""
    assert (bulk.source, bulk.volume, bulk.implied_density) == (one.source, one.volume, one.implied_density)
    assert (bulk.geometry is None) == (one.geometry is None)
    if one.geometry is not None:
        assert bulk.geometry.mass == one.geometry.mass
        assert _same(bulk.geometry.center_of_mass, one.geometry.center_of_mass)
        assert _same(bulk.geometry.inertia_about_com, one.geometry.inertia_about_com)


def test_the_totals_and_torques_of_a_chain_match_a_link_by_link_sum(tmp_path):
    """Every link at the origin's chain of poses, summed independently: the totals, and the
    torque of the first joint against gravity about its own axis."""
    from rbi.core.rotation import euler_matrix
    from rbi.robot import audit

    links = [(1.0 + i % 3, np.diag([1e-3, 2e-3, 2.5e-3])) for i in range(60)]
    path = tmp_path / "chain.urdf"
    path.write_text(_urdf(links, chain=True))
    report = audit(path)
    R_step, p_step = euler_matrix([0.1, 0.0, 0.3], "xyz"), np.array([0.2, 0.0, 0.0])
    R, p, coms = np.eye(3), np.zeros(3), [np.zeros(3)]
    for _ in links[1:]:
        p, R = p + R @ p_step, R @ R_step
        coms.append(p.copy())
    masses = np.array([m for m, _ in links])
    com = (masses[:, None] * np.array(coms)).sum(axis=0) / masses.sum()
    assert report.total.mass == pytest.approx(masses.sum(), rel=1e-15)
    np.testing.assert_allclose(report.total.center_of_mass, com, rtol=1e-12, atol=1e-12)
    axis = R_step @ (np.array([0, 1.0, 1.0]) / np.sqrt(2))  # joint 1's axis in the root frame
    anchor = coms[1]
    first = sum(m * (c - anchor) for m, c in zip(masses[1:], coms[1:]))
    expected = -float(np.array([0, 0, -9.81]) @ np.cross(axis, first))
    assert report.joints[0].torque == pytest.approx(expected, rel=1e-12, abs=1e-12)


def test_a_long_chain_is_read_and_a_loop_in_it_still_named(tmp_path):
    """20,000 links in a chain: the tree check is one pass (it walked to the root from every
    link: 2·10⁸ steps); a loop at the far end is still found and named."""
    from rbi.formats.robot_files import read_robot

    n = 20_000
    parts = ['<robot name="c">'] + [f'<link name="l{i}"/>' for i in range(n)]
    parts += [
        f'<joint name="j{i}" type="fixed"><parent link="l{i - 1}"/><child link="l{i}"/></joint>'
        for i in range(1, n)
    ]
    path = tmp_path / "chain.urdf"
    path.write_text("".join(parts) + "</robot>")
    assert len(read_robot(str(path), geometry=False).links) == n
    looped = "".join(parts).replace(
        '<parent link="l0"/><child link="l1"/>', '<parent link="l3"/><child link="l1"/>'
    )
    looped = looped.replace('<link name="l0"/>', "")
    path.write_text(looped + '<link name="l0"/></robot>')
    with pytest.raises(InputError, match="loop through link"):
        read_robot(str(path), geometry=False)


def test_mass_properties_of_a_stack_equal_the_constructors_bit_for_bit():
    masses = RNG.random(500) * 10.0 ** RNG.integers(-5, 5, size=500)
    centers = RNG.normal(size=(500, 3))
    inertias = np.array([_symmetric(i) for i in range(500)])
    made = MassProperties(masses, centers, inertias, "link")
    for k, value in enumerate(made):
        one = MassProperties(masses[k], centers[k], inertias[k], "link")
        assert value.mass == one.mass and value.frame == one.frame
        assert _same(value.center_of_mass, one.center_of_mass)
        assert _same(value.inertia_about_com, one.inertia_about_com)
        assert not value.center_of_mass.flags.writeable and not value.inertia_about_com.flags.writeable


@pytest.mark.parametrize("shared_name", [False, True])
def test_mass_carried_below_an_unnamed_body_is_looked_for_below_it(shared_name):
    """A heavy root, then a light chain a → (an unnamed MJCF body) → c: nothing below a has mass.
    Below the unnamed body are its own children, not the roots (the walk once looked them up by
    the body's name, None, which is what a root's parent is). Two roots sharing a name are no
    tree of the links' keys: refused, in one line."""
    from rbi.formats.robot import Inertial, LinkTable
    from rbi.robot.audit import _carried

    heavy = Inertial(MassProperties(1.0, np.zeros(3), np.eye(3) * 0.01), np.eye(3) * 0.01)
    table = LinkTable("m.xml", "body")
    for name in ("base", "a", None, "c") + (("d", "d") if shared_name else ()):
        table.add(name, None)
    table.inertials[0] = heavy
    table.parents[1:4] = ["base", "a", table.key(2)]
    if shared_name:
        message = (
            "m.xml: body[5] (d): duplicate body name 'd' (also body[4] (d)); every body needs its own name"
        )
        with pytest.raises(InputError) as refused:
            table.columns()
        assert str(refused.value) == message
        return
    assert _carried(table.columns()) == [False, False, False, False]
