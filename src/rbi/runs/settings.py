"""Checks of a run's settings, made before any work (no spec is read, nothing is integrated).

Each check raises :class:`~rbi.errors.InputError` naming the option as the CLI spells it
(``--duration: must be ...``), so the CLI and :func:`rbi.simulate` report the same line.
"""

from __future__ import annotations

import math
import numbers

from rbi.core.rotation import LARGEST_ANGLE_DEG, angle_is_kept
from rbi.errors import InputError
from rbi.runs.values import vector_value

MAX_SAMPLES = 1_000_000
"""Most samples one run reports (a CSV of 10⁶ rows is about 250 MB)."""


def _finite(value) -> bool:
    try:
        return math.isfinite(value)
    except TypeError:
        return False


def check_run_settings(duration, tilt_axis, gravity, max_steps, rtol) -> None:
    """Refuse the settings that `simulate`, `animate` and `sweep` all take: duration (s, >= 0),
    tilt axis (world x or y), gravity (m/s², >= 0, or None for 9.81), step budget (>= 1 or
    None) and tolerance (in :data:`rbi.sim.api.RTOL_RANGE`, or None for the method's own)."""
    from rbi.sim.api import RTOL_RANGE

    if not (_finite(duration) and duration >= 0.0):
        raise InputError(f"--duration: must be a finite number of seconds >= 0 (got {duration!r})")
    if not isinstance(tilt_axis, str) or tilt_axis.lower() not in ("x", "y"):
        raise InputError(f"--tilt-axis: must be x or y (got {tilt_axis!r})")
    if gravity is not None and not (_finite(gravity) and gravity >= 0.0):
        raise InputError(f"--gravity: must be a finite number of m/s² >= 0 (got {gravity!r})")
    if max_steps is not None and max_steps < 1:
        raise InputError(f"--max-steps: must be at least 1 (got {max_steps!r})")
    if rtol is not None and not (_finite(rtol) and RTOL_RANGE[0] <= rtol < RTOL_RANGE[1]):
        raise InputError(f"--rtol: must be between {RTOL_RANGE[0]:g} and {RTOL_RANGE[1]:g} (got {rtol!r})")


def check_run_options(method, spin, omega, tilt, duration, tilt_axis, gravity, max_steps, rtol) -> None:
    """Refuse the options of one run that `simulate` and `animate` share: the method, the
    initial spin (rad/s about the body z axis) or angular velocity ω (body frame, rad/s; text
    ``"WX,WY,WZ"`` or three numbers), the tilt (deg) and :func:`check_run_settings`'s."""
    from rbi.sim.api import METHODS

    if method not in METHODS:
        raise InputError(f"--method: must be one of {', '.join(METHODS)} (got {method!r})")
    if spin is not None and omega is not None:
        raise InputError("--spin and --omega: give one or the other, not both")
    if spin is not None and not _finite(spin):
        raise InputError(f"--spin: must be a finite number (got {spin!r})")
    if not _finite(tilt):
        raise InputError(f"--tilt: must be a finite number (got {tilt!r})")
    if not angle_is_kept(tilt):
        raise InputError(
            f"--tilt: {tilt!r} degrees is too large to be a turn: rounding loses it "
            f"(at most {LARGEST_ANGLE_DEG:g} degrees)"
        )
    check_run_settings(duration, tilt_axis, gravity, max_steps, rtol)
    if omega is not None:
        vector_value(omega, "--omega")


def check_samples(samples, most: int = MAX_SAMPLES) -> None:
    """Refuse a number of samples outside 1 … ``most``."""
    if isinstance(samples, bool) or not isinstance(samples, numbers.Integral) or not 1 <= samples <= most:
        raise InputError(f"--samples: must be between 1 and {most:,} (got {samples!r})")
