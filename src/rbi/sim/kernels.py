"""The hot loop: right-hand side of the rigid-body equations and an adaptive DOP853 integrator,
written in the subset of Python that numba compiles.

Imported only to compile (just in time, or ahead of time by :mod:`rbi.sim.compiled`); callers
go through :func:`rbi.sim.compiled.integrator`, which loads whichever compiled form exists.

State ``y`` (7,): ``[qw, qx, qy, qz, wx, wy, wz]``: the unit quaternion (scalar first) mapping
body to world coordinates, then the body-frame angular velocity in rad/s.

Equations (body frame, about the fixed point o: the pivot of a top, or the centre of mass of a
free body), with ``I`` the inertia about o in body axes, ``e_z`` the world's up axis seen in
the body (the third row of R(q)) and ``c = m g r_{c/o}`` (zero for a free body)::

    q' = ½ q ⊗ (0, ω)
    I ω' = e_z × c − ω × I ω          (gravity −g e_z acting at the centre of mass)

The integrator is Dormand and Prince's DOP853 (tableau in :mod:`rbi.sim.dop853_tableau`)
with Hairer's step-size control, its 7th-order dense output at the sample times, and the
quaternion projected back to unit length after every accepted step.

Error control: the local error of the quaternion is measured in absolute terms (|q| = 1) and
that of ω relative to ``max(|ω_old|, |ω_new|, omega_ref)``: one tolerance ``rtol`` for both,
independent of the file's units.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from rbi.sim.dop853_tableau import A, B, D, E3, E5

from rbi.sim.compiled import STATUS_DONE, STATUS_MORE, STATUS_NOT_FINITE, STATUS_STEP_TOO_SMALL

NSTATE = 7

SAFETY = 0.9
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0
ERROR_EXPONENT = -1.0 / 8.0

# Argument types of :func:`integrate`, for the ahead-of-time build.
INTEGRATE_SIGNATURE = "i8(f8[:], f8[:], f8[:], f8[:, :], f8[:, :], f8[:, :], f8[:], f8[:], i8[:], i8)"


@njit(cache=True)
def rhs(y, inertia, inertia_inv, c, out):
    """Time derivative of the state ``y`` into ``out`` (see the module docstring)."""
    qw, qx, qy, qz = y[0], y[1], y[2], y[3]
    wx, wy, wz = y[4], y[5], y[6]
    out[0] = 0.5 * (-qx * wx - qy * wy - qz * wz)
    out[1] = 0.5 * (qw * wx + qy * wz - qz * wy)
    out[2] = 0.5 * (qw * wy - qx * wz + qz * wx)
    out[3] = 0.5 * (qw * wz + qx * wy - qy * wx)
    # world up axis in body coordinates: third row of R(q) (homogeneous form, no division)
    ex = 2.0 * (qx * qz - qw * qy)
    ey = 2.0 * (qy * qz + qw * qx)
    ez = qw * qw - qx * qx - qy * qy + qz * qz
    hx = inertia[0, 0] * wx + inertia[0, 1] * wy + inertia[0, 2] * wz
    hy = inertia[1, 0] * wx + inertia[1, 1] * wy + inertia[1, 2] * wz
    hz = inertia[2, 0] * wx + inertia[2, 1] * wy + inertia[2, 2] * wz
    # e_z × c − ω × h
    mx = (ey * c[2] - ez * c[1]) - (wy * hz - wz * hy)
    my = (ez * c[0] - ex * c[2]) - (wz * hx - wx * hz)
    mz = (ex * c[1] - ey * c[0]) - (wx * hy - wy * hx)
    out[4] = inertia_inv[0, 0] * mx + inertia_inv[0, 1] * my + inertia_inv[0, 2] * mz
    out[5] = inertia_inv[1, 0] * mx + inertia_inv[1, 1] * my + inertia_inv[1, 2] * mz
    out[6] = inertia_inv[2, 0] * mx + inertia_inv[2, 1] * my + inertia_inv[2, 2] * mz


@njit(cache=True)
def _stage_state(y, K, s, h, row, out):
    """``out = y + h Σ_{j<s} row[j] K[j]``."""
    for i in range(NSTATE):
        acc = 0.0
        for j in range(s):
            a = row[j]
            if a != 0.0:
                acc += a * K[j, i]
        out[i] = y[i] + h * acc


@njit(cache=True)
def _error_norm(K, h, y, y_new, rtol, omega_ref):
    """Hairer's DOP853 error measure (≤ 1 means the step is accepted)."""
    w_old = np.sqrt(y[4] * y[4] + y[5] * y[5] + y[6] * y[6])
    w_new = np.sqrt(y_new[4] * y_new[4] + y_new[5] * y_new[5] + y_new[6] * y_new[6])
    w_scale = max(w_old, w_new, omega_ref)
    if w_scale == 0.0:
        w_scale = 1.0
    err5 = 0.0
    err3 = 0.0
    for i in range(NSTATE):
        e5 = 0.0
        e3 = 0.0
        for j in range(13):
            e5 += E5[j] * K[j, i]
            e3 += E3[j] * K[j, i]
        scale = rtol if i < 4 else rtol * w_scale
        err5 += (e5 / scale) ** 2
        err3 += (e3 / scale) ** 2
    if err5 == 0.0 and err3 == 0.0:
        return 0.0
    return abs(h) * err5 / np.sqrt((err5 + 0.01 * err3) * NSTATE)


@njit(cache=True)
def _normalise_quaternion(y):
    n = np.sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + y[3] * y[3])
    for i in range(4):
        y[i] /= n


@njit(cache=True)
def integrate(y, clock, t_samples, out, inertia, inertia_inv, c, settings, counts, max_steps):
    """Advance the state, filling ``out[k]`` with the state at ``t_samples[k]``.

    y (7,): current state, updated in place. clock (9,): ``[t, h, f(y)...]``, current time,
    the next trial step and the derivative at y, updated (``h <= 0`` asks for an automatic
    first step and a fresh derivative). t_samples (N,):
    increasing sample times, the last one is where integration stops. out (N, 7).
    settings (2,): ``[rtol, omega_ref]``. counts (4,) int: ``[next sample index, accepted
    steps, rejected steps, rhs evaluations]``, updated. Samples at or before the current time
    are filled from ``y``. Stops after ``max_steps`` steps (returns STATUS_MORE: call again),
    when every sample is filled (STATUS_DONE), or on failure.
    """
    rtol = settings[0]
    omega_ref = settings[1]
    t = clock[0]
    h = clock[1]
    t_end = t_samples[t_samples.shape[0] - 1]
    n_samples = t_samples.shape[0]
    k = counts[0]
    while k < n_samples and t_samples[k] <= t:
        for i in range(NSTATE):
            out[k, i] = y[i]
        k += 1
    counts[0] = k
    if k >= n_samples:
        return STATUS_DONE

    K = np.empty((16, NSTATE))
    y_new = np.empty(NSTATE)
    tmp = np.empty(NSTATE)
    F = np.empty((7, NSTATE))  # dense-output coefficients of the current step
    if h > 0.0:  # continuing: the derivative at y was kept from the last step (first-same-as-last)
        for i in range(NSTATE):
            K[0, i] = clock[2 + i]
    else:
        rhs(y, inertia, inertia_inv, c, K[0])
        counts[3] += 1
    if h <= 0.0:
        # a first step that turns the body by about rtol^(1/8) / 4 radians
        rate = max(omega_ref, np.sqrt(y[4] * y[4] + y[5] * y[5] + y[6] * y[6]))
        h = 0.25 * rtol ** 0.125 / rate if rate > 0.0 else t_end - t
    rejected = False
    steps_here = 0
    while steps_here < max_steps:
        min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
        if h < min_step:
            clock[0] = t
            clock[1] = h
            return STATUS_STEP_TOO_SMALL
        t_new = t + h
        if t_new >= t_end:
            t_new = t_end
        step = t_new - t
        for s in range(1, 12):
            _stage_state(y, K, s, step, A[s], tmp)
            rhs(tmp, inertia, inertia_inv, c, K[s])
        for i in range(NSTATE):
            acc = 0.0
            for j in range(12):
                acc += B[j] * K[j, i]
            y_new[i] = y[i] + step * acc
        rhs(y_new, inertia, inertia_inv, c, K[12])
        counts[3] += 12
        err = _error_norm(K, step, y, y_new, rtol, omega_ref)
        if not np.isfinite(err):
            clock[0] = t
            clock[1] = h
            return STATUS_NOT_FINITE
        if err > 1.0:
            h = step * max(MIN_FACTOR, SAFETY * err ** ERROR_EXPONENT)
            rejected = True
            counts[2] += 1
            continue
        if err == 0.0:
            factor = MAX_FACTOR
        else:
            factor = min(MAX_FACTOR, SAFETY * err ** ERROR_EXPONENT)
        if rejected:
            factor = min(1.0, factor)
        rejected = False
        # samples inside the step: 7th-order dense output
        if k < n_samples and t_samples[k] < t_new:
            for s in range(13, 16):
                _stage_state(y, K, s, step, A[s], tmp)
                rhs(tmp, inertia, inertia_inv, c, K[s])
            counts[3] += 3
            for i in range(NSTATE):
                dy = y_new[i] - y[i]
                F[0, i] = dy
                F[1, i] = step * K[0, i] - dy
                F[2, i] = 2.0 * dy - step * (K[12, i] + K[0, i])
                for m in range(4):
                    acc = 0.0
                    for j in range(16):
                        acc += D[m, j] * K[j, i]
                    F[3 + m, i] = step * acc
            while k < n_samples and t_samples[k] < t_new:
                x = (t_samples[k] - t) / step
                for i in range(NSTATE):
                    v = 0.0
                    for m in range(6, -1, -1):
                        v += F[m, i]
                        v *= x if (6 - m) % 2 == 0 else (1.0 - x)
                    out[k, i] = y[i] + v
                _normalise_quaternion(out[k])
                k += 1
        for i in range(NSTATE):
            y[i] = y_new[i]
        _normalise_quaternion(y)
        t = t_new
        h = step * factor
        counts[1] += 1
        steps_here += 1
        # first-same-as-last; the projection moved y by a rounding-sized amount, too little
        # to be worth a fresh evaluation
        for i in range(NSTATE):
            K[0, i] = K[12, i]
        while k < n_samples and t_samples[k] <= t:
            for i in range(NSTATE):
                out[k, i] = y[i]
            k += 1
        counts[0] = k
        if k >= n_samples:
            clock[0] = t
            clock[1] = h
            return STATUS_DONE
    clock[0] = t
    clock[1] = h
    for i in range(NSTATE):
        clock[2 + i] = K[0, i]
    return STATUS_MORE
