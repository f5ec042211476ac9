"""The plots of `rbi simulate --plot` and `rbi sweep --plot` live in :mod:`rbi.viz.plots`; the
names are kept here for the commands that import them from the CLI."""

from rbi.viz.plots import plot_stability_map, plot_trajectory, require_matplotlib, rotate_by_quaternions  # noqa: F401
