"""Primitive solids: volume, centre of mass and inertia about their own centre of mass.

Every function here works in one consistent set of units chosen by the caller (lengths L,
masses M): inertias come back in M·L². Positions and inertia matrices are expressed in the
body frame. Inertia is ``I = ∫ (|r|² E − r rᵀ) dm`` with ``r`` measured from the part's own
centre of mass, so that shifting to the body's centre of mass later involves only small
differences (see :mod:`rbi.core.inertia`).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike

from rbi.core import polygon
from rbi.core.inertia import re_express as turned  # R I Rᵀ, exactly symmetric; rbi.spec.translate's name
from rbi.core.mass import MassProperties
from rbi.core.rotation import numbers, scalar, unit_vector, vector_length


def axis_between(start: np.ndarray, end: np.ndarray) -> tuple[np.ndarray, float]:
    """Unit vector from ``start`` to ``end`` and the distance between them (L), both computed
    without overflow (the distance is inf only when it exceeds the largest double)."""
    d = numbers(end) - numbers(start)
    return unit_vector(d), scalar(vector_length(d))


def axisymmetric_inertia(axial: ArrayLike, transverse: ArrayLike, axis: ArrayLike) -> np.ndarray:
    """Inertia matrix of a body symmetric about the unit vector ``axis``.

    ``axial`` is the moment about the axis, ``transverse`` about any perpendicular line through
    the same point. Written as ``axial·uuᵀ + transverse·(E − uuᵀ)`` rather than
    ``transverse·E + (axial − transverse)·uuᵀ``: for an axis along a coordinate direction the
    small moment is then exact instead of the difference of two large ones (a thin rod).

    Also for many bodies at once: ``axial`` and ``transverse`` of shape (n,) with ``axis``
    (n, 3) give (n, 3, 3).
    """
    u = numbers(axis)
    uu = u[..., :, None] * u[..., None, :]
    axial = numbers(axial)[..., None, None]
    transverse = numbers(transverse)[..., None, None]
    return axial * uu + transverse * (np.eye(3) - uu)


from typing import Any, TypeAlias  # noqa: E402

Numbers: TypeAlias = Any
"""A float or a numpy array of them (the closed forms below are plain arithmetic on either)."""

# The moments below are plain arithmetic, so they take numbers or whole numpy arrays (many
# parts at once, as rbi.spec.translate.BUILDERS uses them) and give the same bits either way.


def cone_moments(mass: Numbers, radius: Numbers, height: Numbers) -> tuple[Numbers, Numbers]:
    """``(axial, transverse)`` moments of a solid right circular cone about its centre of mass:
    3/10 m r² and 3/80 m (4 r² + h²)."""
    return 0.3 * mass * radius * radius, 3.0 * mass * (4.0 * radius * radius + height * height) / 80.0


def cylinder_moments(mass: Numbers, radius: Numbers, length: Numbers) -> tuple[Numbers, Numbers]:
    """``(axial, transverse)`` moments of a solid circular cylinder about its centre: m r²/2
    and m (3 r² + L²)/12."""
    return 0.5 * mass * radius * radius, mass * (3.0 * radius * radius + length * length) / 12.0


def box_moments(mass: Numbers, a: Numbers, b: Numbers, c: Numbers) -> tuple[Numbers, Numbers, Numbers]:
    """Moments of a solid box with edges a, b, c about its centre, along its own axes:
    m (b² + c²)/12, m (a² + c²)/12, m (a² + b²)/12."""
    return mass / 12.0 * (b * b + c * c), mass / 12.0 * (a * a + c * c), mass / 12.0 * (a * a + b * b)


def sphere_moment(mass: Numbers, radius: Numbers) -> Numbers:
    """Moment 2/5 m r² of a solid sphere about any axis through its centre."""
    return 0.4 * mass * radius * radius


def ellipsoid_moments(mass: Numbers, a: Numbers, b: Numbers, c: Numbers) -> tuple[Numbers, Numbers, Numbers]:
    """Moments of a solid ellipsoid with semi-axes a, b, c about its centre, along its own axes:
    m (b² + c²)/5, m (a² + c²)/5, m (a² + b²)/5."""
    return mass / 5.0 * (b * b + c * c), mass / 5.0 * (a * a + c * c), mass / 5.0 * (a * a + b * b)


def capsule_moments(mass: Numbers, radius: Numbers, length: Numbers) -> tuple[Numbers, Numbers]:
    """``(axial, transverse)`` moments of a solid capsule (a cylinder of length L and radius r
    with a hemisphere on each end) about its centre. The cylinder holds m_c = m L / (L + 4/3 r),
    the caps m_s = m − m_c: axial m_c r²/2 + 2/5 m_s r²; transverse m_c (3 r² + L²)/12 +
    m_s (2/5 r² + L²/4 + 3/8 L r) — the caps' 83/320 m r² about their own centres of mass plus
    the parallel-axis term for their distance L/2 + 3/8 r, gathered so every term is positive."""
    r = radius
    cylinder_mass = mass * length / (length + 4.0 / 3.0 * r)
    caps_mass = mass * (4.0 / 3.0 * r) / (length + 4.0 / 3.0 * r)
    axial = 0.5 * cylinder_mass * r * r + 0.4 * caps_mass * r * r
    transverse = cylinder_mass * (3.0 * r * r + length * length) / 12.0 + caps_mass * (
        0.4 * r * r + 0.25 * length * length + 0.375 * length * r
    )
    return axial, transverse


# --- thin shells: the mass spread evenly over the surface (MuJoCo's shellinertia) -------------


def sphere_area(radius: Numbers) -> Numbers:
    """Surface 4 π r² of a sphere (L²)."""
    return 4.0 * math.pi * radius * radius


def sphere_shell_moment(mass: Numbers, radius: Numbers) -> Numbers:
    """Moment 2/3 m r² of a thin spherical shell about any axis through its centre."""
    return 2.0 / 3.0 * mass * radius * radius


def box_area(a: Numbers, b: Numbers, c: Numbers) -> Numbers:
    """Surface 2 (ab + bc + ca) of a box with edges a, b, c (L²)."""
    return 2.0 * (a * b + b * c + c * a)


def box_shell_moments(mass: Numbers, a: Numbers, b: Numbers, c: Numbers) -> tuple[Numbers, Numbers, Numbers]:
    """Moments of a box's six faces (mass spread evenly over them) about its centre, along its
    own axes. About x: each face across x (area bc) gives σ bc (b² + c²)/12, each across y (area
    ac, at y = ±b/2) σ ac (b²/4 + c²/12), each across z σ ab (b²/12 + c²/4); σ = m / (2 (ab + bc +
    ca)). So I_x = m [bc (b² + c²) + ac (3b² + c²) + ab (b² + 3c²)] / (12 (ab + bc + ca)), the
    others by symmetry."""
    k = mass / (12.0 * (a * b + b * c + c * a))

    def about(p: Numbers, q: Numbers, r: Numbers) -> Numbers:
        """The moment about the axis of edge p, with q and r across it."""
        return k * (q * r * (q * q + r * r) + p * r * (3.0 * q * q + r * r) + p * q * (q * q + 3.0 * r * r))

    return about(a, b, c), about(b, a, c), about(c, a, b)


def cylinder_area(radius: Numbers, length: Numbers) -> Numbers:
    """Surface 2 π r (L + r) of a closed cylinder: its side and two end discs (L²)."""
    return 2.0 * math.pi * radius * (length + radius)


def cylinder_shell_moments(mass: Numbers, radius: Numbers, length: Numbers) -> tuple[Numbers, Numbers]:
    """``(axial, transverse)`` moments of a closed cylinder's surface (side and two end discs,
    mass spread evenly) about its centre. The side (m_s = m L/(L + r)) is a thin tube: m_s r²
    axial, m_s (r²/2 + L²/12) transverse; each disc (m_d = m r/(2 (L + r))) m_d r²/2 axial and
    m_d (r²/4 + L²/4) transverse about the centre."""
    r = radius
    side = mass * length / (length + r)
    discs = mass * r / (length + r)  # both
    axial = side * r * r + 0.5 * discs * r * r
    transverse = side * (0.5 * r * r + length * length / 12.0) + discs * 0.25 * (r * r + length * length)
    return axial, transverse


def capsule_area(radius: Numbers, length: Numbers) -> Numbers:
    """Surface 2 π r (L + 2 r) of a capsule: its cylindrical side and a sphere's worth of caps (L²)."""
    return 2.0 * math.pi * radius * (length + 2.0 * radius)


def capsule_shell_moments(mass: Numbers, radius: Numbers, length: Numbers) -> tuple[Numbers, Numbers]:
    """``(axial, transverse)`` moments of a capsule's surface (mass spread evenly) about its
    centre. The side (m_s = m L/(L + 2r)) is a thin tube: m_s r², m_s (r²/2 + L²/12). The caps
    (m_c = m − m_s) are a spherical shell cut in two and moved L/2 apart along the axis: a
    hemispherical shell has its centroid r/2 from its rim's plane and ∫z² dA = A r²/3, so about
    the centre the caps give 2/3 m_c r² axial and m_c (2/3 r² + r L/2 + L²/4) transverse."""
    r = radius
    side = mass * length / (length + 2.0 * r)
    caps = mass * 2.0 * r / (length + 2.0 * r)
    axial = side * r * r + 2.0 / 3.0 * caps * r * r
    transverse = side * (0.5 * r * r + length * length / 12.0) + caps * (
        2.0 / 3.0 * r * r + 0.5 * r * length + 0.25 * length * length
    )
    return axial, transverse


# --- solid right circular cone -------------------------------------------------------------


def cone_volume(radius: float, height: float) -> float:
    """Volume of a solid right circular cone (L³)."""
    return math.pi * radius * radius * height / 3.0


def cone_center_of_mass(apex: ArrayLike, axis: ArrayLike, height: Numbers) -> np.ndarray:
    """``apex + 3/4 h u``: a cone's centre of mass, a quarter of the height ``h`` above the base,
    with ``axis`` the unit vector ``u`` from the apex to the base. Also for many cones at once:
    ``apex`` and ``axis`` (n, 3), ``height`` (n,)."""
    return numbers(apex) + np.asarray(0.75 * height)[..., None] * axis


# --- solid circular cylinder ---------------------------------------------------------------


def cylinder_volume(radius: float, length: float) -> float:
    """Volume of a solid circular cylinder (L³)."""
    return math.pi * radius * radius * length


def _about_middle(
    mass: float, start: ArrayLike, end: ArrayLike, moments: Callable[[float], tuple[Numbers, Numbers]]
) -> MassProperties:
    """A solid symmetric about the segment ``start`` → ``end`` (L) with its centre of mass in the
    middle; ``moments(length)``: its ``(axial, transverse)`` moments about it (M·L²)."""
    start, end = numbers(start), numbers(end)
    u, length = axis_between(start, end)
    return MassProperties(mass, middle(start, end), axisymmetric_inertia(*moments(length), u))


def middle(start: np.ndarray, end: np.ndarray) -> np.ndarray:
    """``(start + end)/2``: the centre of mass of a solid symmetric about the segment (a cylinder
    between its end faces' centres); for rows of (n, 3) arrays, each row's."""
    return 0.5 * (start + end)


# --- shapes with an orientation --------------------------------------------------------------


def _turned(principal_moments: ArrayLike, rotation: np.ndarray | None) -> np.ndarray:
    """``R diag(moments) Rᵀ``: a part's inertia built along its own axes, expressed in body
    axes. ``rotation`` maps part axes to body axes (None: they coincide). Moments (n, 3) give
    (n, 3, 3)."""
    moments = numbers(principal_moments)
    diagonal = np.zeros((*moments.shape, 3), dtype=moments.dtype)
    diagonal[..., [0, 1, 2], [0, 1, 2]] = moments
    return diagonal if rotation is None else turned(diagonal, rotation)


def _edges(size: ArrayLike) -> tuple[Numbers, Numbers, Numbers]:
    """``a, b, c`` of ``size = [a, b, c]`` as floats, or the columns of sizes (n, 3)."""
    edges = numbers(size)
    if edges.ndim == 1:
        a, b, c = edges.tolist()
        return a, b, c
    return edges[..., 0], edges[..., 1], edges[..., 2]


# --- rectangular box -----------------------------------------------------------------------


def box_volume(size: ArrayLike) -> Numbers:
    """Volume of a rectangular box with edge lengths ``size = [a, b, c]`` (L³); sizes (n, 3)
    give the n volumes."""
    a, b, c = _edges(size)
    return a * b * c


def box_inertia(mass: Numbers, size: ArrayLike, rotation: np.ndarray | None = None) -> np.ndarray:
    """A box's inertia about its centre (:func:`box_moments` along its own axes, turned by
    ``rotation``); masses (n,) with sizes (n, 3) give (n, 3, 3)."""
    return _turned(np.stack(box_moments(mass, *_edges(size)), axis=-1), rotation)


# --- solid ellipsoid -----------------------------------------------------------------------


def ellipsoid_volume(semi_axes: np.ndarray) -> float:
    """Volume 4/3 π a b c of a solid ellipsoid with semi-axes ``[a, b, c]`` (L³)."""
    a, b, c = (scalar(s) for s in semi_axes)
    return 4.0 / 3.0 * math.pi * a * b * c


def ellipsoid(
    mass: float, semi_axes: np.ndarray, center: np.ndarray, rotation: np.ndarray | None = None
) -> MassProperties:
    """Solid ellipsoid with semi-axes ``[a, b, c]`` along its own x, y, z axes.

    About its centre, in its own axes: m (b² + c²)/5, m (a² + c²)/5, m (a² + b²)/5.
    """
    moments = np.array(ellipsoid_moments(mass, *(scalar(s) for s in semi_axes)))
    return MassProperties(mass, numbers(center), _turned(moments, rotation))


def power(x: Numbers, exponent: int) -> Numbers:
    """``x ** exponent``, or inf where a Python number's power leaves a double (Python raises
    OverflowError there, numpy gives inf), so an oversized part reaches its caller's finiteness
    check as numpy's arrays do; any other ``x`` is powered as written, bit for bit."""
    try:
        return x**exponent
    except OverflowError:
        return math.inf


# --- spheres -------------------------------------------------------------------------------


def sphere_volume(radius: float) -> float:
    """Volume of a solid sphere (L³)."""
    return 4.0 / 3.0 * math.pi * power(radius, 3)


def sphere_inertia(mass: Numbers, radius: Numbers) -> np.ndarray:
    """A solid sphere's inertia about its centre, :func:`sphere_moment` times E; masses and radii
    (n,) give (n, 3, 3)."""
    return np.asarray(sphere_moment(mass, radius))[..., None, None] * np.eye(3)


def spherical_shell_volume(outer_radius: float, inner_radius: float) -> float:
    """Volume 4/3 π (R³ − r³) of a thick spherical shell, written as
    4/3 π (R − r)(R² + R r + r²) so that a thin wall keeps its digits (L³)."""
    R, r = outer_radius, inner_radius
    return 4.0 / 3.0 * math.pi * (R - r) * (R * R + R * r + r * r)


def spherical_shell(
    mass: float, outer_radius: float, inner_radius: float, center: np.ndarray
) -> MassProperties:
    """Thick spherical shell (a sphere of radius R with a concentric hole of radius r).

    Moment about any axis through the centre: 2/5 m (R⁵ − r⁵)/(R³ − r³), evaluated as
    2/5 m (R⁴ + R³r + R²r² + Rr³ + r⁴)/(R² + Rr + r²), which has no cancellation and is
    exact in the limits: r = 0 gives the solid sphere (2/5 m R²), r = R the thin shell
    (2/3 m R²).
    """
    R, r = outer_radius, inner_radius
    quartic = power(R, 4) + power(R, 3) * r + R * R * r * r + R * power(r, 3) + power(r, 4)
    ratio = quartic / (R * R + R * r + r * r)
    return MassProperties(mass, numbers(center), 0.4 * mass * ratio * np.eye(3))


# --- tube (hollow circular cylinder) ---------------------------------------------------------


def tube_volume(outer_radius: float, inner_radius: float, length: float) -> float:
    """Volume π (R − r)(R + r) L of a tube (L³); a thin wall keeps its digits."""
    R, r = outer_radius, inner_radius
    return math.pi * (R - r) * (R + r) * length


def tube(
    mass: float, outer_radius: float, inner_radius: float, start: np.ndarray, end: np.ndarray
) -> MassProperties:
    """Hollow circular cylinder (outer radius R, bore r) between the centres of its end faces.

    About its centre: axial m (R² + r²)/2, transverse m (3 (R² + r²) + L²)/12. r = 0 gives
    the solid cylinder, r = R a thin-walled tube.
    """
    squares = outer_radius * outer_radius + inner_radius * inner_radius
    return _about_middle(
        mass,
        start,
        end,
        lambda length: (0.5 * mass * squares, mass * (3.0 * squares + length * length) / 12.0),
    )


# --- frustum (truncated cone) ----------------------------------------------------------------


def frustum_volume(start_radius: float, end_radius: float, length: float) -> float:
    """Volume π h (a² + a b + b²)/3 of a truncated cone with end radii a, b (L³)."""
    a, b = start_radius, end_radius
    return math.pi * length * (a * a + a * b + b * b) / 3.0


def frustum(
    mass: float, start_radius: float, end_radius: float, start: np.ndarray, end: np.ndarray
) -> MassProperties:
    """Solid truncated cone: a disc of radius a centred on ``start``, one of radius b on
    ``end`` (either radius may be 0, giving a cone; a = b gives a cylinder).

    With S = a² + ab + b² and h = |end − start|:
    centre of mass at h (a² + 2ab + 3b²)/(4 S) from ``start``;
    axial moment 3/10 m (a⁴ + a³b + a²b² + ab³ + b⁴)/S;
    transverse moment about the centre of mass
    3/20 m (a⁴ + a³b + a²b² + ab³ + b⁴)/S + 3/80 m h² (a⁴ + 4a³b + 10a²b² + 4ab³ + b⁴)/S².
    Every term is positive, so no digits cancel. The ratios are evaluated on a/c and b/c with
    c = max(a, b) (then multiplied by c²), so radii near 1e-160 or 1e160 neither underflow to
    0/0 nor overflow in the fourth powers.
    """
    c = max(scalar(start_radius), scalar(end_radius), key=lambda r: r.real)
    a, b = scalar(start_radius) / c, scalar(end_radius) / c
    start = numbers(start)
    u, h = axis_between(start, end)
    S = a * a + a * b + b * b
    quartic = a**4 + a**3 * b + a * a * b * b + a * b**3 + b**4
    along = h * (a * a + 2.0 * a * b + 3.0 * b * b) / (4.0 * S)
    axial = 0.3 * mass * c * c * quartic / S
    spread = a**4 + 4.0 * a**3 * b + 10.0 * a * a * b * b + 4.0 * a * b**3 + b**4
    transverse = 0.15 * mass * c * c * quartic / S + 3.0 * mass * h * h * spread / (80.0 * S * S)
    return MassProperties(mass, start + along * u, axisymmetric_inertia(axial, transverse, u))


# --- thin rod --------------------------------------------------------------------------------


def rod(mass: float, start: np.ndarray, end: np.ndarray) -> MassProperties:
    """Thin straight rod (a line mass) from ``start`` to ``end``: m L²/12 about any line
    through its middle perpendicular to it, 0 about its own axis."""
    return _about_middle(mass, start, end, lambda length: (0.0, mass * length * length / 12.0))


# --- torus -----------------------------------------------------------------------------------


def torus_volume(major_radius: float, minor_radius: float) -> float:
    """Volume 2 π² R a² of a solid torus (ring radius R, tube radius a) (L³)."""
    return 2.0 * math.pi * math.pi * major_radius * minor_radius * minor_radius


def torus(
    mass: float, major_radius: float, minor_radius: float, center: np.ndarray, axis: np.ndarray
) -> MassProperties:
    """Solid torus: a disc of radius a (``minor_radius``) swept around ``axis`` at distance R
    (``major_radius``) from ``center``. Needs a ≤ R.

    About its centre: axial moment m (R² + 3/4 a²), transverse (about a diameter)
    m (R²/2 + 5/8 a²) (Pappus: each ring of the tube's cross-section adds its own ring
    moment).
    """
    u = unit_vector(axis)
    R2, a2 = major_radius * major_radius, minor_radius * minor_radius
    axial = mass * (R2 + 0.75 * a2)
    transverse = mass * (0.5 * R2 + 0.625 * a2)
    return MassProperties(mass, numbers(center), axisymmetric_inertia(axial, transverse, u))


# --- hemisphere ------------------------------------------------------------------------------


def hemisphere_volume(radius: float) -> float:
    """Volume 2/3 π r³ of a solid hemisphere (L³)."""
    return 2.0 / 3.0 * math.pi * power(radius, 3)


HEMISPHERE_COM_FRACTION = 3.0 / 8.0
"""Distance of a solid hemisphere's centre of mass from its flat face, as a fraction of r."""


def hemisphere(mass: float, radius: float, center: np.ndarray, axis: np.ndarray) -> MassProperties:
    """Solid hemisphere: flat face centred on ``center``, dome towards ``axis``.

    The centre of mass lies 3/8 r along the axis. About the flat face's centre every moment is
    2/5 m r² (half a sphere); moved to the centre of mass, the axial moment stays 2/5 m r² and
    the transverse one becomes (2/5 − 9/64) m r² = 83/320 m r².
    """
    u = unit_vector(axis)
    r2 = radius * radius
    com = numbers(center) + HEMISPHERE_COM_FRACTION * radius * u
    return MassProperties(mass, com, axisymmetric_inertia(0.4 * mass * r2, 83.0 / 320.0 * mass * r2, u))


# --- capsule ---------------------------------------------------------------------------------


def capsule_volume(radius: float, length: float) -> float:
    """Volume π r² (L + 4/3 r) of a capsule: a cylinder of length L and two hemispherical caps
    (L³)."""
    return math.pi * radius * radius * (length + 4.0 / 3.0 * radius)


def capsule(mass: float, radius: float, start: np.ndarray, end: np.ndarray) -> MassProperties:
    """Capsule: a solid cylinder from ``start`` to ``end`` (length L) with a hemisphere of the
    same radius r on each end face, uniform density; moments about its centre as
    :func:`capsule_moments` gives them."""
    return _about_middle(mass, start, end, lambda length: capsule_moments(mass, scalar(radius), length))


# --- prism: a plane polygon with holes extruded along a straight line ------------------------


def prism_frame(
    start: ArrayLike, end: ArrayLike, x_axis: ArrayLike | None = None
) -> tuple[np.ndarray, float]:
    """``(R, L)``: the outline's axes as the columns of ``R`` (body axes) and the length
    ``L = |end − start|``. z runs from ``start`` to ``end``; x is ``x_axis`` (default body x, or
    body y when x runs along z) made perpendicular to z; y = z × x. ValueError when ``x_axis``
    runs along z."""
    z, length = axis_between(numbers(start), numbers(end))
    for x in [x_axis] if x_axis is not None else [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]:
        x = unit_vector(x)
        x = x - (x @ z) * z
        if vector_length(x) >= 1e-9:
            break
    else:
        raise ValueError("x_axis: runs along the extrusion (end - start); give a direction across it")
    x = unit_vector(x)
    return np.column_stack((x, np.cross(z, x), z)), length


def prism_volume(outline: ArrayLike, holes: list, start: ArrayLike, end: ArrayLike) -> float:
    """Volume of the prism (L³): the outline's area less its holes', times the length."""
    return polygon.area_moments(outline, holes)[0] * scalar(vector_length(np.subtract(end, start)))


def prism(
    mass: float,
    outline: ArrayLike,
    holes: list,
    start: ArrayLike,
    end: ArrayLike,
    x_axis: ArrayLike | None = None,
) -> MassProperties:
    """Straight extrusion of the outline less its holes (outline coordinates in the axes of
    :func:`prism_frame`, origin at ``start``) from ``start`` to ``end``. With area A, second
    moments J of the section about its centroid and length L, along its own axes about its centre
    of mass: Ixx = m (Jyy/A + L²/12)... precisely ``m (J_yy/A + L²/12)`` about x with J_yy =
    ∫y'², ``m (J_xx/A + L²/12)`` about y, ``m (J_xx + J_yy)/A`` about z, product ``−m J_xy/A``."""
    R, length = prism_frame(start, end, x_axis)
    area, (cx, cy), J = polygon.area_moments(outline, holes)
    extra = length * length / 12.0
    jxx, jyy, jxy = J[0, 0] / area, J[1, 1] / area, J[0, 1] / area  # ∫x'², ∫y'², ∫x'y' per area
    own = mass * np.array([[jyy + extra, -jxy, 0.0], [-jxy, jxx + extra, 0.0], [0.0, 0.0, jxx + jyy]])
    com = numbers(start) + R @ [cx, cy, 0.5 * length]
    return MassProperties(mass, com, turned(own, R))
