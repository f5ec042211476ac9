"""`rbi simulate --plot`: the path of the spin axis seen from above, tilt (or, for a free body,
each principal axis's turn) against time, ω and the energy drift; `rbi sweep --plot`: the
stability map.

matplotlib is an optional extra (``pip install '.[plot]' from rbi's source folder, or pip install matplotlib``); it is imported only here.
"""

from __future__ import annotations

import numpy as np

from rbi.core.rotation import rotate
from rbi.files.output import write_output
from rbi.viz.frames import AXIS_COLOURS
from rbi.viz.labels import MAX_LABEL_CHARS, label, plain, pyplot


def plot_trajectory(
    columns: dict[str, np.ndarray],
    target,
    title: str = "",
    *,
    principal_axes=None,
    inertia=None,
    energy_unit: str = "J",
    spin_axis=(0.0, 0.0, 1.0),
) -> None:
    """Four panels written at the checked output ``target`` (its format; replaced atomically): the
    path of the tip of the spin axis (``spin_axis``, unit, body frame) seen from above,
    coloured by time; the tilt of that axis against time (a top) or, when ``principal_axes``
    (body frame, rows, ascending moments) and the ``inertia`` about the centre of mass (body
    axes) are given (a free body), the angle between each principal axis and the angular
    momentum (fixed in space), where a flip of the intermediate axis shows as a swing from
    0° to 180°; the body-frame ω components; and the drift of the total energy. ``title``: a
    run's :func:`rbi.viz.labels.motion_title`."""
    plt = pyplot()

    t = np.asarray(columns["t"], dtype=float)
    q = np.column_stack([columns[k] for k in ("qw", "qx", "qy", "qz")])
    tip = rotate(q, spin_axis)  # unit spin axis, world frame
    fig, axes = plt.subplots(2, 2, figsize=(12, 8.4), gridspec_kw={"width_ratios": [1.45, 1]})
    (angle_ax, above), (omega_ax, energy_ax) = axes

    _angle_panel(angle_ax, t, q, columns, principal_axes, inertia)
    _above_panel(fig, above, t, tip)
    _omega_panel(omega_ax, t, columns)
    _energy_panel(energy_ax, t, columns, energy_unit)
    for ax in (angle_ax, omega_ax, energy_ax):
        ax.set_xlabel("time [s]")
    for ax in axes.flat:
        ax.grid(alpha=0.3)
    if title:
        plain(fig.suptitle(label(title, 2 * MAX_LABEL_CHARS)))
    fig.tight_layout()
    write_output(target, writer=lambda path: fig.savefig(path, format=target.format, dpi=110))
    plt.close(fig)


def _angle_panel(angle_ax, t: np.ndarray, q: np.ndarray, columns: dict, principal_axes, inertia) -> None:
    """The spin axis's tilt against time (a top), or each principal axis's angle to the angular
    momentum (a free body: ``principal_axes`` rows and ``inertia`` about the CoM, body frame)."""
    if principal_axes is None:
        angle_ax.plot(t, columns["tilt_deg"], lw=1.0, color="#1f77b4")
        top = max(float(np.max(columns["tilt_deg"])) if t.size else 0.0, 1.0)
        angle_ax.set(ylabel="tilt of the spin axis from vertical [deg]", ylim=(-0.05 * top, 1.1 * top))
    else:
        omega0 = np.array([columns["wx"][0], columns["wy"][0], columns["wz"][0]])
        momentum = rotate(q[0], np.asarray(inertia, dtype=float) @ omega0)
        direction = momentum / (np.linalg.norm(momentum) or 1.0)
        axes = np.asarray(principal_axes, dtype=float)
        for k, (axis, colour, name) in enumerate(
            zip(axes, AXIS_COLOURS, ("smallest", "intermediate", "largest"))
        ):
            angle = np.degrees(np.arccos(np.clip(rotate(q, axis) @ direction, -1.0, 1.0)))
            angle_ax.plot(t, angle, lw=1.1, color=colour, label=f"axis of the {name} moment (I{k + 1})")
        angle_ax.set(
            ylim=(-5, 185), yticks=[0, 45, 90, 135, 180], ylabel="angle to the angular momentum [deg]"
        )
        angle_ax.legend(loc="upper right", fontsize=8, framealpha=0.9)


def _above_panel(fig, above, t: np.ndarray, tip: np.ndarray) -> None:
    """The tip of the unit spin axis (world frame) seen from above, coloured by time."""
    from matplotlib.collections import LineCollection  # optional extra `plot`, loaded only to draw
    from matplotlib.ticker import MaxNLocator  # optional extra `plot`, loaded only to draw

    x, y = tip[:, 0], tip[:, 1]
    reach = float(np.max(np.hypot(x, y))) if t.size else 0.0
    extent = max(1.15 * reach, np.sin(np.radians(1.0)))  # an upright top still gets a readable frame
    if t.size > 1:
        segments = np.stack((np.column_stack((x[:-1], y[:-1])), np.column_stack((x[1:], y[1:]))), axis=1)
        line = LineCollection(segments, cmap="viridis", linewidths=1.0)
        line.set_array(0.5 * (t[:-1] + t[1:]))
        above.add_collection(line)
        fig.colorbar(line, ax=above, label="time [s]", fraction=0.046, pad=0.04)
    above.plot(x[:1], y[:1], "o", ms=11, mfc="none", mec="black", mew=1.6, label=f"start (t = {t[0]:g} s)")
    above.plot(x[-1:], y[-1:], "s", ms=5, color="#d62728", label=f"end (t = {t[-1]:g} s)")
    if reach < 1e-9:
        above.text(0.5, 0.12, "the axis stays vertical", transform=above.transAxes, ha="center", fontsize=9)
    above.set(xlim=(-extent, extent), ylim=(-extent, extent), aspect="equal")
    above.xaxis.set_major_locator(MaxNLocator(5))
    above.yaxis.set_major_locator(MaxNLocator(5))
    above.set(xlabel="world x (tip of the unit spin axis)", ylabel="world y")
    above.set_title("spin axis seen from above", fontsize=10)
    above.legend(loc="upper left", fontsize=8, framealpha=0.9)


def _omega_panel(omega_ax, t: np.ndarray, columns: dict) -> None:
    """The body-frame angular velocity components against time."""
    for key, colour in (("wx", "#d62728"), ("wy", "#2ca02c"), ("wz", "#1f77b4")):
        omega_ax.plot(t, columns[key], lw=0.9, color=colour, label=f"ω{key[1]}")
    omega_ax.set_ylabel("ω in body axes [rad/s]")
    omega_ax.legend(loc="upper right", fontsize=8, ncols=3, framealpha=0.9)


def _energy_panel(energy_ax, t: np.ndarray, columns: dict, energy_unit: str) -> None:
    """The drift of the total energy from its first value."""
    energy = np.asarray(columns["energy"], dtype=float)
    drift = energy - energy[0]
    scale = float(np.max(np.abs(energy))) or 1.0
    energy_ax.plot(t, drift, lw=0.9, color="#444444")
    energy_ax.set_ylabel(f"energy − initial energy [{energy_unit}]")
    energy_ax.set_title(f"energy drift (largest {np.max(np.abs(drift)) / scale:.1e} of |E|)", fontsize=10)
    energy_ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 3))


def plot_stability_map(
    x, y, values, target, x_label: str, y_label: str | None, threshold: float | None = None, title: str = ""
) -> None:
    """The largest tilt of each run (log colour scale) over one or two swept axes, written at the
    checked output ``target`` (its format; replaced atomically). With one axis: tilt against it.
    ``threshold``: the sleeping-top spin (rad/s), drawn as a vertical line on a spin axis."""
    plt = pyplot()

    xs, ys = np.asarray(x, dtype=float), y
    values = np.array([np.nan if v is None else float(v) for v in values])
    finite = np.isfinite(values)
    fig, ax = plt.subplots(figsize=(8, 5.2))
    if ys is None:
        _tilt_against_one_axis(ax, xs, values, finite)
    else:
        _tilt_over_two_axes(fig, ax, xs, np.asarray(ys, dtype=float), values, finite, y_label)
    if threshold is not None and np.isfinite(threshold):
        colour = "white" if ys is not None else "black"
        name = f"sleeping-top threshold {threshold:.4g} rad/s (closed form)"
        ax.axvline(threshold, color=colour, ls="--", lw=1.2, label=name)
    plain(ax.set_xlabel(label(x_label, 2 * MAX_LABEL_CHARS)))
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc="lower left", fontsize=8, framealpha=0.85)
    if title:
        plain(ax.set_title(label(title, 2 * MAX_LABEL_CHARS)))
    fig.tight_layout()
    write_output(target, writer=lambda path: fig.savefig(path, format=target.format, dpi=120))
    plt.close(fig)


def _tilt_against_one_axis(ax, xs: np.ndarray, values: np.ndarray, finite: np.ndarray) -> None:
    """The largest tilt of each run against the one swept axis (in the axis' order: drawn values
    come in any order); failed runs marked on the floor."""
    order = np.argsort(xs[finite], kind="stable")
    ax.semilogy(xs[finite][order], np.maximum(values[finite], 1e-6)[order], "o-", ms=3, lw=1)
    ax.set_ylabel("largest tilt [deg]")
    if np.any(~finite):
        floor = np.full(int(np.sum(~finite)), ax.get_ylim()[0])
        ax.plot(xs[~finite], floor, "x", color="red", label="failed run")


def _tilt_over_two_axes(
    fig, ax, xs: np.ndarray, ys: np.ndarray, values: np.ndarray, finite: np.ndarray, y_label
) -> None:
    """The largest tilt of each run in colour (log scale) over two swept axes: a mesh for a full
    grid, points otherwise; failed runs marked."""
    from matplotlib.colors import LogNorm  # optional extra `plot`, loaded only to draw

    positive = values[finite & (values > 0)]
    low = max(float(np.min(positive)), 1e-6) if positive.size else 1e-3
    high = max(float(np.max(positive)), low * 10) if positive.size else 1.0
    norm = LogNorm(low, high)
    x_values, y_values = np.unique(xs), np.unique(ys)
    if x_values.size > 1 and y_values.size > 1 and x_values.size * y_values.size == xs.size:
        grid = np.full((y_values.size, x_values.size), np.nan)
        grid[np.searchsorted(y_values, ys), np.searchsorted(x_values, xs)] = np.where(
            finite, np.maximum(values, low), np.nan
        )
        mesh = ax.pcolormesh(x_values, y_values, grid, norm=norm, shading="nearest", cmap="viridis")
    else:
        mesh = ax.scatter(
            xs[finite], ys[finite], c=np.maximum(values[finite], low), norm=norm, cmap="viridis", s=18
        )
    if np.any(~finite):
        ax.plot(xs[~finite], ys[~finite], "x", color="red", label="failed run")
    fig.colorbar(mesh, ax=ax, label="largest tilt [deg] (log scale)")
    plain(ax.set_ylabel(label(y_label, 2 * MAX_LABEL_CHARS)))
