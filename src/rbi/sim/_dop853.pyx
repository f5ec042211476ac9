# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
"""The hot loop, compiled when the package is built: the rigid-body right-hand side inlined
into an adaptive DOP853 integrator whose tableau is a compile-time constant.

State ``y`` (7,): ``[qw, qx, qy, qz, wx, wy, wz]``: the unit quaternion (scalar first) mapping
body to world coordinates, then the body-frame angular velocity in rad/s.

Equations (body frame, about the fixed point o: the pivot of a top, or the centre of mass of a
free body), with ``I`` the inertia about o in body axes, ``e_z`` the world's up axis seen in
the body (the third row of R(q)) and ``c = m g r_{c/o}`` (zero for a free body)::

    q' = ½ q ⊗ (0, ω)
    I ω' = e_z × c − ω × I ω          (gravity −g e_z acting at the centre of mass)

Dormand and Prince's DOP853 with Hairer's step-size control, its 7th-order dense output at the
sample times, and the quaternion projected back to unit length after every accepted step.
Error control: the quaternion's local error is measured in absolute terms (|q| = 1), that of ω
relative to ``max(|ω_old|, |ω_new|, omega_ref)``: one tolerance ``rtol`` for both.

Entries: :func:`integrate` (one run, resumable in chunks) and :func:`integrate_batch` (many runs
in one call, spread over threads without the GIL).
"""

from cython.parallel cimport prange
from libc.math cimport sqrt, fabs, pow, nextafter, INFINITY, isfinite
from libc.stdint cimport int64_t

cdef extern from *:
    """
    #ifdef _OPENMP
    #define RBI_OPENMP 1
    #else
    #define RBI_OPENMP 0
    #endif
    """
    const int RBI_OPENMP

cdef extern from "_dop853_tableau.h":
    const double DOP853_A[16][16]
    const double DOP853_B[12]
    const double DOP853_D[4][16]
    const double DOP853_E3[13]
    const double DOP853_E5[13]

STATUS_DONE = 0
STATUS_MORE = 1
STATUS_STEP_TOO_SMALL = 2
STATUS_NOT_FINITE = 3

cdef enum:
    NSTATE = 7
    DONE = 0
    MORE = 1
    STEP_TOO_SMALL = 2
    NOT_FINITE = 3

cdef double SAFETY = 0.9
cdef double MIN_FACTOR = 0.2
cdef double MAX_FACTOR = 10.0
cdef double ERROR_EXPONENT = -1.0 / 8.0


cdef inline void rhs(const double* y, const double* I, const double* Iinv, const double* c,
                     double* out) noexcept nogil:
    """Time derivative of ``y`` into ``out``; I, Iinv row-major 3×3, c (3,)."""
    cdef double qw = y[0], qx = y[1], qy = y[2], qz = y[3]
    cdef double wx = y[4], wy = y[5], wz = y[6]
    cdef double ex, ey, ez, hx, hy, hz, mx, my, mz
    out[0] = 0.5 * (-qx * wx - qy * wy - qz * wz)
    out[1] = 0.5 * (qw * wx + qy * wz - qz * wy)
    out[2] = 0.5 * (qw * wy - qx * wz + qz * wx)
    out[3] = 0.5 * (qw * wz + qx * wy - qy * wx)
    # world up axis in body coordinates: third row of R(q) (homogeneous form, no division)
    ex = 2.0 * (qx * qz - qw * qy)
    ey = 2.0 * (qy * qz + qw * qx)
    ez = qw * qw - qx * qx - qy * qy + qz * qz
    hx = I[0] * wx + I[1] * wy + I[2] * wz
    hy = I[3] * wx + I[4] * wy + I[5] * wz
    hz = I[6] * wx + I[7] * wy + I[8] * wz
    mx = (ey * c[2] - ez * c[1]) - (wy * hz - wz * hy)
    my = (ez * c[0] - ex * c[2]) - (wz * hx - wx * hz)
    mz = (ex * c[1] - ey * c[0]) - (wx * hy - wy * hx)
    out[4] = Iinv[0] * mx + Iinv[1] * my + Iinv[2] * mz
    out[5] = Iinv[3] * mx + Iinv[4] * my + Iinv[5] * mz
    out[6] = Iinv[6] * mx + Iinv[7] * my + Iinv[8] * mz


cdef inline void stage_state(const double* y, double K[16][7], int s, double h, double* out) noexcept nogil:
    """``out = y + h Σ_{j<s} A[s][j] K[j]``."""
    cdef int i, j
    cdef double acc, a
    for i in range(NSTATE):
        acc = 0.0
        for j in range(s):
            a = DOP853_A[s][j]
            if a != 0.0:
                acc += a * K[j][i]
        out[i] = y[i] + h * acc


cdef inline double error_norm(double K[16][7], double h, const double* y, const double* y_new,
                              double rtol, double omega_ref) noexcept nogil:
    """Hairer's DOP853 error measure (≤ 1 means the step is accepted)."""
    cdef double w_old = sqrt(y[4] * y[4] + y[5] * y[5] + y[6] * y[6])
    cdef double w_new = sqrt(y_new[4] * y_new[4] + y_new[5] * y_new[5] + y_new[6] * y_new[6])
    cdef double w_scale = w_old
    cdef double err5 = 0.0, err3 = 0.0, e5, e3, scale
    cdef int i, j
    if w_new > w_scale:
        w_scale = w_new
    if omega_ref > w_scale:
        w_scale = omega_ref
    if w_scale == 0.0:
        w_scale = 1.0
    for i in range(NSTATE):
        e5 = 0.0
        e3 = 0.0
        for j in range(13):
            e5 += DOP853_E5[j] * K[j][i]
            e3 += DOP853_E3[j] * K[j][i]
        scale = rtol if i < 4 else rtol * w_scale
        err5 += (e5 / scale) * (e5 / scale)
        err3 += (e3 / scale) * (e3 / scale)
    if err5 == 0.0 and err3 == 0.0:
        return 0.0
    return fabs(h) * err5 / sqrt((err5 + 0.01 * err3) * NSTATE)


cdef inline void normalise_quaternion(double* y) noexcept nogil:
    cdef double n = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + y[3] * y[3])
    cdef int i
    for i in range(4):
        y[i] /= n


cdef inline void dop853_step(const double* y, double K[16][7], double step, double* y_new, double* tmp,
                             const double* I, const double* Iinv, const double* c) noexcept nogil:
    """One DOP853 step of size ``step`` from ``y`` (whose derivative is already in ``K[0]``):
    stages ``K[1..11]``, the 8th-order result ``y_new`` and its derivative ``K[12]``."""
    cdef int i, j, s
    cdef double acc
    for s in range(1, 12):
        stage_state(y, K, s, step, tmp)
        rhs(tmp, I, Iinv, c, K[s])
    for i in range(NSTATE):
        acc = 0.0
        for j in range(12):
            acc += DOP853_B[j] * K[j][i]
        y_new[i] = y[i] + step * acc
    rhs(y_new, I, Iinv, c, K[12])


cdef inline double accepted_step_factor(double err, bint after_rejection) noexcept nogil:
    """How much to grow (or shrink) the step after an accepted step with error norm ``err``:
    never more than MAX_FACTOR, and not at all right after a rejected step."""
    cdef double factor
    if err == 0.0:
        factor = MAX_FACTOR
    else:
        factor = SAFETY * pow(err, ERROR_EXPONENT)
        if factor > MAX_FACTOR:
            factor = MAX_FACTOR
    if after_rejection and factor > 1.0:
        factor = 1.0
    return factor


cdef inline void dense_coefficients(const double* y, const double* y_new, double K[16][7], double step,
                                    double F[7][7], double* tmp, const double* I, const double* Iinv,
                                    const double* c) noexcept nogil:
    """The 7th-order interpolant over the step from ``y`` to ``y_new``: three more stages into
    ``K[13..15]``, then the coefficients ``F`` that :func:`dense_sample` evaluates."""
    cdef int i, j, s, m
    cdef double dy, acc
    for s in range(13, 16):
        stage_state(y, K, s, step, tmp)
        rhs(tmp, I, Iinv, c, K[s])
    for i in range(NSTATE):
        dy = y_new[i] - y[i]
        F[0][i] = dy
        F[1][i] = step * K[0][i] - dy
        F[2][i] = 2.0 * dy - step * (K[12][i] + K[0][i])
        for m in range(4):
            acc = 0.0
            for j in range(16):
                acc += DOP853_D[m][j] * K[j][i]
            F[3 + m][i] = step * acc


cdef inline void dense_sample(const double* y, double F[7][7], double x, double* out) noexcept nogil:
    """The state at the fraction ``x`` of the step (0 at its start, 1 at its end) into ``out``,
    its quaternion projected back to unit length."""
    cdef int i, m
    cdef double v
    for i in range(NSTATE):
        v = 0.0
        for m in range(6, -1, -1):
            v += F[m][i]
            if (6 - m) % 2 == 0:
                v *= x
            else:
                v *= (1.0 - x)
        out[i] = y[i] + v
    normalise_quaternion(out)


cdef inline Py_ssize_t samples_up_to(const double* y, double t, const double* t_samples, Py_ssize_t k,
                                     Py_ssize_t n, double* out) noexcept nogil:
    """``y`` into the samples from ``k`` on at times <= ``t``; returns the next sample to fill."""
    cdef int i
    while k < n and t_samples[k] <= t:
        for i in range(NSTATE):
            out[k * NSTATE + i] = y[i]
        k += 1
    return k


cdef inline double first_step(const double* y, double rtol, double omega_ref, double span) noexcept nogil:
    """A first step turning the body by about rtol^(1/8) / 4 radians (``span`` if it does not turn)."""
    cdef double rate = sqrt(y[4] * y[4] + y[5] * y[5] + y[6] * y[6])
    if omega_ref > rate:
        rate = omega_ref
    return 0.25 * pow(rtol, 0.125) / rate if rate > 0.0 else span


cdef inline Py_ssize_t accept_step(double* y, const double* y_new, double K[16][7], double F[7][7], double* tmp,
                                   double t, double t_new, double step, const double* t_samples, Py_ssize_t k,
                                   Py_ssize_t n, double* out, const double* I, const double* Iinv,
                                   const double* c, int64_t* rhs_evals) noexcept nogil:
    """Accept the step from ``y`` (at ``t``) to ``y_new`` (at ``t_new``): samples inside it by dense
    output (3 evaluations, counted unless ``rhs_evals`` is NULL), ``y`` = ``y_new`` projected to
    unit |q|, f(y) into ``K[0]``, samples at ``t_new``. Returns the next sample to fill."""
    cdef int i
    if k < n and t_samples[k] < t_new:
        dense_coefficients(y, y_new, K, step, F, tmp, I, Iinv, c)
        if rhs_evals != NULL:
            rhs_evals[0] += 3
        while k < n and t_samples[k] < t_new:
            dense_sample(y, F, (t_samples[k] - t) / step, &out[k * NSTATE])
            k += 1
    # first-same-as-last; the projection moves y by a rounding-sized amount, too little to be
    # worth a fresh evaluation
    for i in range(NSTATE):
        y[i] = y_new[i]
        K[0][i] = K[12][i]
    normalise_quaternion(y)
    return samples_up_to(y, t_new, t_samples, k, n, out)


cdef int advance(double* y, double* clock, const double* t_samples, Py_ssize_t n_samples, double* out,
                 const double* I, const double* Iinv, const double* c, double rtol, double omega_ref,
                 int64_t* counts, int64_t max_steps) noexcept nogil:
    """Advance one run; see :func:`integrate` for the meaning of the arguments."""
    cdef double K[16][7]
    cdef double F[7][7]
    cdef double y_new[7]
    cdef double tmp[7]
    cdef double t = clock[0], h = clock[1], t_end = t_samples[n_samples - 1]
    cdef double t_new, step, err, factor, min_step
    cdef Py_ssize_t k = counts[0]
    cdef int i
    cdef bint rejected = False
    cdef int64_t steps_here = 0

    k = samples_up_to(y, t, t_samples, k, n_samples, out)
    counts[0] = k
    if k >= n_samples:
        return DONE

    if h > 0.0:  # continuing: the derivative at y was kept from the last step (first-same-as-last)
        for i in range(NSTATE):
            K[0][i] = clock[2 + i]
    else:
        rhs(y, I, Iinv, c, K[0])
        counts[3] += 1
        h = first_step(y, rtol, omega_ref, t_end - t)

    while steps_here < max_steps:
        min_step = 10.0 * fabs(nextafter(t, INFINITY) - t)
        if h < min_step:
            clock[0] = t
            clock[1] = h
            return STEP_TOO_SMALL
        t_new = t + h
        if t_new >= t_end:
            t_new = t_end
        step = t_new - t
        dop853_step(y, K, step, y_new, tmp, I, Iinv, c)
        counts[3] += 12
        err = error_norm(K, step, y, y_new, rtol, omega_ref)
        if not isfinite(err):
            clock[0] = t
            clock[1] = h
            return NOT_FINITE
        if err > 1.0:
            factor = SAFETY * pow(err, ERROR_EXPONENT)
            h = step * (factor if factor > MIN_FACTOR else MIN_FACTOR)
            rejected = True
            counts[2] += 1
            continue
        factor = accepted_step_factor(err, rejected)
        rejected = False
        k = accept_step(y, y_new, K, F, tmp, t, t_new, step, t_samples, k, n_samples, out, I, Iinv, c, &counts[3])
        t = t_new
        h = step * factor
        counts[1] += 1
        steps_here += 1
        counts[0] = k
        if k >= n_samples:
            clock[0] = t
            clock[1] = h
            return DONE
    clock[0] = t
    clock[1] = h
    for i in range(NSTATE):
        clock[2 + i] = K[0][i]
    return MORE


def integrate(double[::1] y, double[::1] clock, const double[::1] t_samples, double[:, ::1] out,
              const double[:, ::1] inertia, const double[:, ::1] inertia_inv, const double[::1] c,
              const double[::1] settings, int64_t[::1] counts, int64_t max_steps):
    """Advance one run, filling ``out[k]`` with the state at ``t_samples[k]``; returns a status.

    y (7,): current state, updated in place. clock (9,): ``[t, h, f(y)...]``: current time, the
    next trial step and the derivative at y, updated (``h <= 0`` asks for an automatic first
    step). t_samples (N,): increasing sample times; the last is where integration stops.
    out (N, 7). inertia, inertia_inv (3, 3): about the fixed point, body axes. c (3,): m g r.
    settings (2,): ``[rtol, omega_ref]``. counts (4,) int64: ``[next sample index, accepted
    steps, rejected steps, rhs evaluations]``, updated. Returns STATUS_MORE after ``max_steps``
    steps (call again to continue), STATUS_DONE when every sample is filled, or a failure.
    """
    if y.shape[0] != NSTATE or clock.shape[0] != 9 or counts.shape[0] != 4 or settings.shape[0] != 2:
        raise ValueError("integrate: y (7,), clock (9,), settings (2,) and counts (4,) expected")
    if out.shape[0] != t_samples.shape[0] or out.shape[1] != NSTATE or t_samples.shape[0] < 1:
        raise ValueError("integrate: out must be (len(t_samples), 7) with at least one sample")
    if inertia.shape[0] != 3 or inertia.shape[1] != 3 or inertia_inv.shape[0] != 3 \
            or inertia_inv.shape[1] != 3 or c.shape[0] != 3:
        raise ValueError("integrate: inertia and inertia_inv (3, 3), c (3,) expected")
    cdef int status
    with nogil:
        status = advance(&y[0], &clock[0], &t_samples[0], t_samples.shape[0], &out[0, 0], &inertia[0, 0],
                         &inertia_inv[0, 0], &c[0], settings[0], settings[1], &counts[0], max_steps)
    return status


def integrate_batch(const double[:, ::1] y0, const double[::1] t_samples, const double[:, :, ::1] inertia,
                    const double[:, :, ::1] inertia_inv, const double[:, ::1] c, const double[::1] omega_ref,
                    double rtol, int64_t max_steps, double[:, :, ::1] out, int64_t[:, ::1] counts,
                    int64_t[::1] status, int threads=1):
    """Integrate B independent runs from t = 0, each to the end of ``t_samples``, in parallel.

    y0 (B, 7) initial states; t_samples (N,) shared sample times; inertia, inertia_inv (B, 3, 3);
    c (B, 3); omega_ref (B,); out (B, N, 7) filled; counts (B, 4) and status (B,) written per
    run (a run that needs more than ``max_steps`` steps ends with STATUS_MORE). threads: the
    cores to spread them over, at least 1. Each run takes exactly the steps :func:`integrate`
    takes for it.
    """
    cdef Py_ssize_t B = y0.shape[0], N = t_samples.shape[0], r
    if y0.shape[1] != NSTATE or N < 1 or inertia.shape[0] != B or inertia_inv.shape[0] != B \
            or c.shape[0] != B or omega_ref.shape[0] != B or out.shape[0] != B or out.shape[1] != N \
            or out.shape[2] != NSTATE or counts.shape[0] != B or counts.shape[1] != 4 or status.shape[0] != B:
        raise ValueError("integrate_batch: inconsistent array shapes")
    if inertia.shape[1] != 3 or inertia.shape[2] != 3 or inertia_inv.shape[1] != 3 \
            or inertia_inv.shape[2] != 3 or c.shape[1] != 3:
        raise ValueError("integrate_batch: inertia (B, 3, 3) and c (B, 3) expected")
    if threads < 1:
        raise ValueError("integrate_batch: threads must be at least 1")
    if B == 0:
        return
    for r in prange(B, nogil=True, schedule="dynamic", chunksize=1, num_threads=threads):
        _run_one(&y0[r, 0], &t_samples[0], N, &out[r, 0, 0], &inertia[r, 0, 0], &inertia_inv[r, 0, 0],
                 &c[r, 0], rtol, omega_ref[r], &counts[r, 0], max_steps, &status[r])


cdef void _run_one(const double* y0, const double* t_samples, Py_ssize_t n, double* out, const double* I,
                   const double* Iinv, const double* c, double rtol, double omega_ref, int64_t* counts,
                   int64_t max_steps, int64_t* status) noexcept nogil:
    cdef double y[7]
    cdef double clock[9]
    cdef int i
    for i in range(NSTATE):
        y[i] = y0[i]
    for i in range(9):
        clock[i] = 0.0
    for i in range(4):
        counts[i] = 0
    status[0] = advance(y, clock, t_samples, n, out, I, Iinv, c, rtol, omega_ref, counts, max_steps)


def openmp_enabled():
    """True when this module was compiled with OpenMP (the runs of a batch share the cores)."""
    return bool(RBI_OPENMP)


cdef Py_ssize_t _minimal_loop(double* y, const double* t_samples, Py_ssize_t n, double* out, const double* I,
                              const double* Iinv, const double* c, double rtol, double omega_ref) noexcept nogil:
    """DOP853 from t = 0 to ``t_samples[n - 1]`` in one straight loop: no chunks, no resuming,
    no step budget, no counters but the step count, no failure exits. The same arithmetic as
    :func:`advance`, so the same steps and the same samples."""
    cdef double K[16][7]
    cdef double F[7][7]
    cdef double y_new[7]
    cdef double tmp[7]
    cdef double t = 0.0, h, t_end = t_samples[n - 1], t_new, step, err, factor
    cdef Py_ssize_t k = 0, steps = 0
    cdef bint rejected = False
    k = samples_up_to(y, t, t_samples, k, n, out)
    if k >= n:
        return 0
    rhs(y, I, Iinv, c, K[0])
    h = first_step(y, rtol, omega_ref, t_end - t)
    while k < n:
        t_new = t + h
        if t_new >= t_end:
            t_new = t_end
        step = t_new - t
        if not step > 0.0:  # the step underflowed: give up rather than loop forever
            return -1
        dop853_step(y, K, step, y_new, tmp, I, Iinv, c)
        err = error_norm(K, step, y, y_new, rtol, omega_ref)
        if err > 1.0:
            factor = SAFETY * pow(err, ERROR_EXPONENT)
            h = step * (factor if factor > MIN_FACTOR else MIN_FACTOR)
            rejected = True
            continue
        factor = accepted_step_factor(err, rejected)
        rejected = False
        k = accept_step(y, y_new, K, F, tmp, t, t_new, step, t_samples, k, n, out, I, Iinv, c, NULL)
        t = t_new
        h = step * factor
        steps += 1
    return steps


def integrate_minimal(double[::1] y, const double[::1] t_samples, const double[:, ::1] inertia,
                      const double[:, ::1] inertia_inv, const double[::1] c, double rtol, double omega_ref,
                      double[:, ::1] out):
    """The benchmark's baseline (``rbi bench``, section kernel): the smallest loop that takes
    the same DOP853 steps as :func:`integrate` and gives the same samples, with none of the
    machinery a command needs (chunks for progress and Ctrl-C, a step budget, counters,
    failure statuses, shape checks beyond memory safety). Fills ``out`` (N, 7) and returns the
    number of accepted steps (−1 if the step size underflowed); ``y`` (7,) ends as the final state. Not used by rbi's commands."""
    if y.shape[0] != NSTATE or out.shape[0] != t_samples.shape[0] or out.shape[1] != NSTATE \
            or t_samples.shape[0] < 1 or inertia.shape[0] != 3 or inertia.shape[1] != 3 \
            or inertia_inv.shape[0] != 3 or inertia_inv.shape[1] != 3 or c.shape[0] != 3:
        raise ValueError("integrate_minimal: y (7,), out (N, 7), inertia (3, 3), c (3,) expected")
    cdef Py_ssize_t steps
    with nogil:
        steps = _minimal_loop(&y[0], &t_samples[0], t_samples.shape[0], &out[0, 0], &inertia[0, 0],
                              &inertia_inv[0, 0], &c[0], rtol, omega_ref)
    return steps
