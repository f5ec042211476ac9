"""`rbi simulate --plot`: tilt against time and the path of the body z axis seen from above.

matplotlib is an optional extra (``pip install '.[plot]' from rbi's source folder, or pip install matplotlib``); it is imported only here.
"""

from __future__ import annotations

import numpy as np

from rbi.spec.errors import InputError


def require_matplotlib() -> None:
    """InputError with the install command when matplotlib is missing."""
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        raise InputError("--plot: needs matplotlib, which is not installed: pip install '.[plot]' from rbi's source folder, or pip install matplotlib") from None


def plot_trajectory(columns: dict[str, np.ndarray], path: str, title: str = "", format: str = "png") -> None:
    """Two panels saved as a PNG at ``path``: the tilt of the body z axis from vertical against
    time, and the path of that axis's tip (unit length) projected on the horizontal plane."""
    require_matplotlib()
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = columns["t"]
    tilt = columns["tilt_deg"]
    azimuth = np.nan_to_num(np.radians(columns["precession_deg"]))  # undefined while vertical: radius 0
    radius = np.sin(np.radians(tilt))
    x, y = radius * np.cos(azimuth), radius * np.sin(azimuth)
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.8), gridspec_kw={"width_ratios": [1.6, 1]})
    left.plot(t, tilt, lw=1.0)
    left.set_xlabel("time [s]")
    left.set_ylabel("tilt of body z axis from vertical [deg]")
    left.grid(alpha=0.3)
    right.plot(x, y, lw=0.8)
    right.plot(x[:1], y[:1], "o", ms=4, label="start")
    right.plot(x[-1:], y[-1:], "s", ms=4, label="end")
    extent = max(float(np.max(np.abs(np.concatenate((x, y))))), 1e-12) * 1.1
    right.set_xlim(-extent, extent)
    right.set_ylim(-extent, extent)
    right.set_aspect("equal")
    right.set_xlabel("world x (tip of unit body z axis)")
    right.set_ylabel("world y")
    right.set_title("seen from above", fontsize=10)
    right.legend(loc="upper right", fontsize=8)
    right.grid(alpha=0.3)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, format=format, dpi=120)
    plt.close(fig)
