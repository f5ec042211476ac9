"""What a trajectory knows about its own accuracy, and what the scene's stability is.

Public names:

- :func:`tilt_deg`, :func:`precession_deg`: geometry of samples. The tilt
  and precession are those of the scene's spin axis: pass ``scene.spin_frame`` (see
  :attr:`rbi.sim.scene.Scene.spin_frame`); without it, of the body z axis.
- :func:`energy`, :func:`angular_momentum_world`: along a trajectory.
- :func:`conserved_quantities` ``(scene, q, omega) -> dict``: every quantity the scene
  conserves (energy; vertical angular momentum about the pivot; the spin of an axisymmetric
  top; the whole angular momentum vector of a free body), each with its relative drift.
- :func:`orientation_error_deg`: the angle between two orientations.
- :func:`symmetry_axis`: the axis of an axisymmetric top (or None).
- :func:`stability`: the sleeping-top criterion, or the intermediate-axis (Dzhanibekov) verdict.

Frames: q [w, x, y, z] maps body to world; omega is in the body frame (rad/s). Energies are in
M·L²/s², angular momenta in M·L²/s, about the pivot (or the centre of mass of a free body).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from rbi.core.rotation import (
    quaternion_conjugate,
    quaternion_multiply,
    rotate,
    up_in_body,
    vector_length,
    z_axis_in_world,
)
from rbi.sim.scene import Scene

AXISYMMETRY_RTOL = 1e-9
"""Two principal moments this close (relative) count as equal."""


def in_spin_frame(q: np.ndarray, frame: np.ndarray | None) -> np.ndarray:
    """``q ⊗ frame`` (N, 4): the orientation whose z axis is the spin axis that ``frame`` (a
    scene's :attr:`~rbi.sim.scene.Scene.spin_frame`) turns body z onto; ``q`` itself for None."""
    q = np.atleast_2d(q)
    if frame is None:
        return q
    return quaternion_multiply(q, frame)


def spin_axis_in_world(q: np.ndarray, frame: np.ndarray | None = None) -> np.ndarray:
    """The spin axis in world coordinates, ``R(q) a`` (N, 3); the body z axis without ``frame``."""
    return z_axis_in_world(in_spin_frame(q, frame))


def tilt_deg(q: np.ndarray, frame: np.ndarray | None = None) -> np.ndarray:
    """Tilt: the angle between the spin axis (body z without ``frame``) and the upward vertical,
    degrees (N,).

    ``2 atan2(√(x²+y²), √(w²+z²))`` of ``q ⊗ frame``: accurate near 0 and 180 degrees.
    """
    q = in_spin_frame(q, frame)
    return np.degrees(2.0 * np.arctan2(np.hypot(q[:, 1], q[:, 2]), np.hypot(q[:, 0], q[:, 3])))


VERTICAL_TOLERANCE = 1e-12
"""Horizontal extent of the unit spin axis below which it counts as vertical: its azimuth
(the precession angle) is then undefined."""


def precession_deg(q: np.ndarray, frame: np.ndarray | None = None) -> np.ndarray:
    """Precession: the azimuth of the spin axis's horizontal projection seen from above (world x
    towards y), degrees, unwrapped so that it is continuous along the samples (N,). NaN where
    the axis is vertical (within :data:`VERTICAL_TOLERANCE`), since the azimuth is undefined
    there."""
    axis = spin_axis_in_world(q, frame)
    defined = np.hypot(axis[:, 0], axis[:, 1]) > VERTICAL_TOLERANCE
    out = np.full(axis.shape[0], np.nan)
    if np.any(defined):
        out[defined] = np.degrees(np.unwrap(np.arctan2(axis[defined, 1], axis[defined, 0])))
    return out


def energy(scene: Scene, q: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """Total energy (N,): kinetic ``½ ωᵀ I ω`` about the fixed point plus gravity's
    ``m g z_com`` (height of the centre of mass above the pivot), M·L²/s²."""
    return kinetic_energy(scene, omega) + potential_energy(scene, q)


def kinetic_energy(scene: Scene, omega: np.ndarray) -> np.ndarray:
    omega = np.atleast_2d(omega)
    return 0.5 * np.einsum("ni,ij,nj->n", omega, scene.inertia, omega)


def potential_energy(scene: Scene, q: np.ndarray) -> np.ndarray:
    return up_in_body(np.atleast_2d(q)) @ scene.gravity_moment


def angular_momentum_body(scene: Scene, omega: np.ndarray) -> np.ndarray:
    """``I ω`` (N, 3) about the fixed point, body axes."""
    return np.atleast_2d(omega) @ scene.inertia.T


def angular_momentum_world(scene: Scene, q: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """``R (I ω)`` (N, 3) about the fixed point, world axes."""

    return rotate(np.atleast_2d(q), angular_momentum_body(scene, omega))


def symmetry_axis(scene: Scene) -> np.ndarray | None:
    """Unit symmetry axis (body frame) when the scene is an axisymmetric top (two equal
    principal moments about the fixed point, centre of mass on the third axis) or a free body
    with two equal moments; otherwise None. Points towards the centre of mass when there is
    an offset."""
    moments, axes = scene.principal_moments, scene.principal_axes
    scale = moments[-1]
    if abs(moments[1] - moments[0]) <= AXISYMMETRY_RTOL * scale:
        axis = axes[2]
    elif abs(moments[2] - moments[1]) <= AXISYMMETRY_RTOL * scale:
        axis = axes[0]
    else:
        return None
    r = np.asarray(scene.com_from_pivot, dtype=float)
    length = float(np.linalg.norm(r))
    if length == 0.0:
        return axis
    if np.linalg.norm(np.cross(axis, r)) > AXISYMMETRY_RTOL * length:
        return None
    return axis if axis @ r > 0 else -axis


def conserved_quantities(scene: Scene, q: np.ndarray, omega: np.ndarray) -> dict[str, dict[str, Any]]:
    """The scene's invariants along the samples, each as ``{"initial", "drift", "unit"}``.

    ``drift`` is ``max |value(t) − value(0)|`` relative to the quantity's size along the run
    (energy: the largest kinetic plus |potential| energy; momenta: the largest |h|), so that
    a quantity that happens to start at zero still gets a meaningful relative drift.
    """
    q = np.atleast_2d(q)
    omega = np.atleast_2d(omega)
    h_body = angular_momentum_body(scene, omega)
    h_size = float(np.max(vector_length(h_body)))
    initial, drift = energy_drifts(scene, q[None], omega[None])
    out: dict[str, dict[str, Any]] = {
        "energy": {"initial": float(initial[0]), "drift": drift[0], "unit": "energy"}
    }
    if scene.pivoted:
        h_vertical = np.einsum("ni,ni->n", up_in_body(q), h_body)
        out["h_vertical"] = _drift(h_vertical, h_size)
        axis = symmetry_axis(scene)
        if axis is not None:
            out["h_spin"] = _drift(h_body @ axis, h_size)
    else:
        out["h_world"] = _drift(angular_momentum_world(scene, q, omega), h_size)
    return out


def energy_drifts(scene: Scene, q: np.ndarray, omega: np.ndarray) -> tuple[np.ndarray, list[float]]:
    """For each of B runs (q (B, N, 4), omega (B, N, 3)): the initial total energy (M·L²/s²)
    and its relative drift, ``max |E(t) − E(0)|`` over the run's largest kinetic plus
    |potential| energy (the energy entry of :func:`conserved_quantities`, and a sweep row's)."""
    B, N = q.shape[0], q.shape[1]
    kinetic = kinetic_energy(scene, omega.reshape(B * N, 3)).reshape(B, N)
    potential = potential_energy(scene, q.reshape(B * N, 4)).reshape(B, N)
    total = kinetic + potential
    change = np.max(np.abs(total - total[:, :1]), axis=1)
    size = np.max(kinetic + np.abs(potential), axis=1)
    return total[:, 0], [_relative(float(c), float(s)) for c, s in zip(change, size)]


def _drift(values: np.ndarray, size: float) -> dict[str, Any]:
    """The entry of an angular momentum along the samples, (N,) or (N, 3): its first value and
    its largest change from it (a vector's: in length) relative to ``size``."""
    change = values - values[0]
    largest = np.max(np.abs(change) if values.ndim == 1 else vector_length(change))
    return {
        "initial": float(values[0]) if values.ndim == 1 else values[0],
        "drift": _relative(float(largest), size),
        "unit": "angular_momentum",
    }


def _relative(change: float, size: float) -> float:
    return change / size if size > 0.0 else 0.0


def orientation_error_deg(q: np.ndarray, r: np.ndarray) -> np.ndarray:
    """Angle of the rotation taking orientation ``r`` to ``q`` (degrees, (N,) or scalar), by
    ``2 atan2(|vector part|, |scalar part|)`` of ``r* q``: accurate for tiny angles, blind to
    the sign of either quaternion."""
    q = np.atleast_2d(q) / np.linalg.norm(np.atleast_2d(q), axis=1)[:, None]
    r = np.atleast_2d(r) / np.linalg.norm(np.atleast_2d(r), axis=1)[:, None]
    turn = quaternion_multiply(quaternion_conjugate(r), q)
    angle = np.degrees(2.0 * np.arctan2(np.linalg.norm(turn[:, 1:], axis=1), np.abs(turn[:, 0])))
    return angle if angle.size > 1 else float(angle[0])


def axial_and_transverse(scene: Scene, axis: np.ndarray) -> tuple[float, float]:
    """The moments (M·L²) of an axisymmetric scene about its symmetry ``axis`` (unit, body
    frame) and about a line across it through the fixed point (the other principal moment)."""
    axial = float(axis @ scene.inertia @ axis)
    moments = scene.principal_moments
    return axial, float(moments[2] if abs(moments[0] - axial) < abs(moments[2] - axial) else moments[0])


def sleeping_threshold(scene: Scene) -> dict[str, float] | None:
    """The sleeping-top threshold of an axisymmetric top with its centre of mass above the
    pivot on the axis: ``ω₃² = 4 m g l I₁ / I₃²`` (I₁ the transverse moment about the pivot).
    Returns ``{"omega3", "I1", "I3", "l"}`` or None when it does not apply."""
    axis = symmetry_axis(scene)
    length = float(np.linalg.norm(scene.com_from_pivot))
    if not scene.pivoted or axis is None or length == 0.0 or scene.gravity <= 0.0:
        return None
    I3, I1 = axial_and_transverse(scene, axis)
    omega3 = math.sqrt(4.0 * scene.mass * scene.gravity * length * I1) / I3
    return {"omega3": omega3, "I1": I1, "I3": I3, "l": length}


def stability(scene: Scene, q0: np.ndarray, omega0: np.ndarray) -> dict[str, Any]:
    """A plain statement of the stability of the motion started from ``(q0, omega0)``.

    Axisymmetric top: compares the spin about the symmetry axis with the sleeping-top
    threshold (upright spin stable above it, unstable below). Free body: which principal axis
    the spin is closest to; near the intermediate axis the spin is unstable (Dzhanibekov).
    Returns ``{"kind", "verdict", ...}`` with numbers for scripts.
    """
    omega0 = np.asarray(omega0, dtype=float)
    if scene.pivoted:
        return _top_stability(scene, q0, omega0)
    return _free_stability(scene, omega0)


LEVEL_TOLERANCE = 1e-9
"""The centre of mass counts as level with the pivot when the sine of its elevation seen from the
pivot is below this."""


def com_elevation(scene: Scene, q0: np.ndarray) -> str:
    """Where the centre of mass starts relative to the pivot: ``"above"``, ``"below"`` or
    ``"level"`` (its height over the pivot within :data:`LEVEL_TOLERANCE` of its distance)."""
    r = np.asarray(scene.com_from_pivot, dtype=float)
    length = float(np.linalg.norm(r))
    height = float(up_in_body(q0) @ r)
    if length == 0.0 or abs(height) <= LEVEL_TOLERANCE * length:
        return "level"
    return "above" if height > 0.0 else "below"


def _top_stability(scene: Scene, q0, omega0) -> dict[str, Any]:
    length = float(np.linalg.norm(scene.com_from_pivot))
    if length == 0.0 or scene.gravity <= 0.0:
        return {
            "kind": "balanced",
            "verdict": "the centre of mass is at the pivot: gravity exerts no torque, "
            "the body turns as a free body",
        }
    where = com_elevation(scene, q0)
    said = {"above": "above", "below": "below", "level": "level with"}[where]
    threshold = sleeping_threshold(scene)
    if threshold is None:
        return {
            "kind": "asymmetric top",
            "com_position": where,
            "verdict": f"the centre of mass starts {said} the pivot, off any symmetry axis of the body, so the "
            "sleeping-top criterion does not apply: gravity pulls at a point off the spin axis "
            "and the top wobbles from the start",
        }
    axis = symmetry_axis(scene)
    spin = float(omega0 @ axis)
    result = {
        "kind": "axisymmetric top",
        "com_position": where,
        "sleeping_threshold_rad_s": threshold["omega3"],
        "spin_rad_s": spin,
        "above_threshold": abs(spin) > threshold["omega3"],
    }
    if where == "below":
        result["verdict"] = (
            "the centre of mass starts below the pivot: the hanging position is stable whatever the spin"
        )
        return result
    if where == "level":
        return _level_top(scene, result, threshold, spin)
    return _upright_top(result, threshold, spin, axis, q0, omega0)


def _level_top(scene: Scene, result: dict[str, Any], threshold: dict, spin: float) -> dict[str, Any]:
    """The verdict for an axisymmetric top whose centre of mass starts level with the pivot:
    a pendulum without spin, else a gyroscope precessing at m g l / (I₃ ω)."""
    w = f"{abs(spin):.6g} rad/s"
    if spin == 0.0:
        result["verdict"] = (
            "the centre of mass starts level with the pivot and the body does not spin about "
            "its axis: it swings down like a pendulum"
        )
        return result
    rate = scene.mass * scene.gravity * threshold["l"] / (threshold["I3"] * abs(spin))
    result["gyroscopic_precession_rad_s"] = rate
    result["verdict"] = (
        f"the centre of mass starts level with the pivot, spinning at {w} about its axis: "
        f"gravity's torque turns the axis sideways, a gyroscope precessing at about "
        f"{rate:.6g} rad/s (m g l / (I₃ ω), fast-spin approximation)"
    )
    return result


def _upright_top(
    result: dict[str, Any], threshold: dict, spin: float, axis: np.ndarray, q0, omega0
) -> dict[str, Any]:
    """The verdict for an axisymmetric top whose centre of mass starts above the pivot: stable
    above the sleeping-top threshold, unstable below it."""
    w = f"{abs(spin):.6g} rad/s"
    limit = f"{threshold['omega3']:.6g} rad/s"
    up = float(up_in_body(q0) @ axis)
    if abs(spin) > threshold["omega3"]:
        result["verdict"] = (
            f"the centre of mass starts above the pivot; spin {w} is above the sleeping-top "
            f"threshold {limit} (ω₃² = 4 m g l I₁ / I₃²): the upright spin is stable, a small "
            f"tilt only nutates"
        )
    else:
        result["verdict"] = (
            f"the centre of mass starts above the pivot; spin {w} is below the sleeping-top "
            f"threshold {limit} (ω₃² = 4 m g l I₁ / I₃²): the upright spin is unstable, any small "
            f"tilt grows and the top falls away from vertical"
        )
        if up >= 1.0 and not np.any(np.cross(omega0, axis)):
            result["verdict"] += (
                " (started exactly upright it stays up, an unstable equilibrium: any "
                "perturbation, such as a nudge of --tilt 0.01, makes it fall)"
            )
    return result


def _free_stability(scene: Scene, omega0) -> dict[str, Any]:
    moments, axes = scene.principal_moments, scene.principal_axes
    h = moments * (axes @ omega0)  # principal components of I ω
    if not np.any(h):
        return {"kind": "free body", "verdict": "not rotating"}
    scale = moments[-1]
    if moments[2] - moments[0] <= AXISYMMETRY_RTOL * scale:
        return {"kind": "free body", "verdict": "spherical inertia: ω stays constant, every axis is stable"}
    # share of the kinetic energy carried by each principal axis
    share = h * h / moments
    nearest = int(np.argmax(share))
    result = {"kind": "free body", "principal_moments": moments, "nearest_axis": nearest + 1}
    # two equal moments: symmetry_axis's test (a free body's centre of mass is its fixed point)
    if symmetry_axis(scene) is not None:
        result["verdict"] = (
            "axisymmetric body: ω precesses steadily about the symmetry axis, the motion is stable"
        )
        return result
    name = ("smallest", "intermediate", "largest")[nearest]
    if nearest == 1:
        result["intermediate_axis"] = True
        result["verdict"] = (
            "spin near the intermediate principal axis: unstable (Dzhanibekov effect), "
            "the body flips over periodically"
        )
    else:
        result["intermediate_axis"] = False
        result["verdict"] = f"spin near the {name}-moment principal axis: stable (the body wobbles about it)"
    return result
