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


def plot_stability_map(xs, ys, values, path: str, x_label: str, y_label: str | None, threshold: float | None = None,
                       title: str = "", format: str = "png") -> None:
    """The largest tilt of each run (log colour scale) over one or two swept axes, saved at
    ``path``. With one axis: tilt against it. ``threshold``: the sleeping-top spin (rad/s),
    drawn as a vertical line on a spin axis."""
    require_matplotlib()
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import LogNorm

    xs = np.asarray(xs, dtype=float)
    values = np.array([np.nan if v is None else float(v) for v in values])
    finite = np.isfinite(values)
    fig, ax = plt.subplots(figsize=(8, 5.2))
    if ys is None:
        ax.semilogy(xs[finite], np.maximum(values[finite], 1e-6), "o-", ms=3, lw=1)
        ax.set_ylabel("largest tilt [deg]")
        if np.any(~finite):
            ax.plot(xs[~finite], np.full(int(np.sum(~finite)), ax.get_ylim()[0]), "x", color="red", label="failed run")
    else:
        ys = np.asarray(ys, dtype=float)
        positive = values[finite & (values > 0)]
        low = max(float(np.min(positive)), 1e-6) if positive.size else 1e-3
        high = max(float(np.max(positive)), low * 10) if positive.size else 1.0
        x_values, y_values = np.unique(xs), np.unique(ys)
        if x_values.size > 1 and y_values.size > 1 and x_values.size * y_values.size == xs.size:
            grid = np.full((y_values.size, x_values.size), np.nan)
            grid[np.searchsorted(y_values, ys), np.searchsorted(x_values, xs)] = np.where(finite, np.maximum(values, low), np.nan)
            mesh = ax.pcolormesh(x_values, y_values, grid, norm=LogNorm(low, high), shading="nearest", cmap="viridis")
        else:
            mesh = ax.scatter(xs[finite], ys[finite], c=np.maximum(values[finite], low), norm=LogNorm(low, high),
                              cmap="viridis", s=18)
        if np.any(~finite):
            ax.plot(xs[~finite], ys[~finite], "x", color="red", label="failed run")
        fig.colorbar(mesh, ax=ax, label="largest tilt [deg] (log scale)")
        ax.set_ylabel(y_label)
    if threshold is not None and np.isfinite(threshold):
        ax.axvline(threshold, color="white" if ys is not None else "black", ls="--", lw=1.2,
                   label=f"sleeping-top threshold {threshold:.4g} rad/s (closed form)")
    ax.set_xlabel(x_label)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc="lower left", fontsize=8, framealpha=0.85)
    if title:
        ax.set_title(title)
    fig.tight_layout()
    fig.savefig(path, format=format, dpi=120)
    plt.close(fig)
