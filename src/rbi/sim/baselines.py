"""The seed chapter's own set-up, for comparison: scipy's ``solve_ivp`` with a right-hand side
written in plain Python that builds the rotation matrix with scipy's ``Rotation`` at every
call, on the raw state ``[qw, qx, qy, qz, wx, wy, wz]`` (the quaternion is not renormalised).

The chapter used ``method="RK45", rtol=1e-8, atol=1e-10``; ``solve_with_scipy`` takes any of
scipy's explicit methods and tolerances. Same equations and frames as :mod:`rbi.sim.kernels`.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import DOP853, RK45
from scipy.spatial.transform import Rotation

from rbi.sim.scene import Scene


def python_rhs(scene: Scene):
    """``f(t, y)`` in the chapter's style: rotation matrix from scipy, torque of gravity at the
    centre of mass mapped into the body frame, Euler's equations about the pivot."""

    inertia = scene.inertia
    inertia_inv = np.linalg.inv(inertia)
    r_com = scene.com_from_pivot
    weight_world = np.array([0.0, 0.0, -scene.mass * scene.gravity])

    def f(t, y):
        q = y[:4]
        omega = y[4:]
        R = Rotation.from_quat([q[1], q[2], q[3], q[0]]).as_matrix()  # scipy wants [x, y, z, w]
        torque_body = R.T @ np.cross(R @ r_com, weight_world)
        alpha = inertia_inv @ (torque_body - np.cross(omega, inertia @ omega))
        w, x, yq, z = q
        dq = 0.5 * np.array(
            [
                -x * omega[0] - yq * omega[1] - z * omega[2],
                w * omega[0] + yq * omega[2] - z * omega[1],
                w * omega[1] - x * omega[2] + z * omega[0],
                w * omega[2] + x * omega[1] - yq * omega[0],
            ]
        )
        return [*dq, *alpha]

    return f


def solve_with_scipy(scene: Scene, q0, omega0, t_samples: np.ndarray, method: str, rtol: float, atol: float):
    """Integrate with scipy's ``RK45`` or ``DOP853`` solver class, stepping as ``solve_ivp``
    does (so the accepted steps can be counted) and sampling by the solver's dense output.

    Returns ``(y (7, N), accepted_steps, rhs_evaluations)``; raises RuntimeError on failure.
    """

    solver_class = {"RK45": RK45, "DOP853": DOP853}[method]
    y0 = np.concatenate((np.asarray(q0, dtype=float), np.asarray(omega0, dtype=float)))
    t_end = float(t_samples[-1])
    out = np.empty((7, t_samples.size))
    k = 0
    while k < t_samples.size and t_samples[k] <= 0.0:
        out[:, k] = y0
        k += 1
    if k == t_samples.size:
        return out, 0, 0
    solver = solver_class(python_rhs(scene), 0.0, y0, t_end, rtol=rtol, atol=atol)
    steps = 0
    while k < t_samples.size:
        message = solver.step()
        if solver.status == "failed":
            raise RuntimeError(f"scipy {method}: {message}")
        steps += 1
        dense = None
        while k < t_samples.size and t_samples[k] <= solver.t:
            if t_samples[k] == solver.t:
                out[:, k] = solver.y
            else:
                if dense is None:
                    dense = solver.dense_output()
                out[:, k] = dense(t_samples[k])
            k += 1
    return out, steps, int(solver.nfev)
