"""The runs of a sweep: grid axes, Monte Carlo draws, and the values of run ``i``.

A grid axis takes one number, a sequence of numbers or a :class:`Grid` (evenly spaced values);
a drawn axis a :class:`Normal` or :class:`Uniform` distribution. The runs are the
product of the grid axes in the order spin, tilt, then each ``--vary`` in the order given (the
last axis changes fastest), each repeated ``runs`` times with fresh draws; run ``i``'s values
are computed from ``i`` alone, so any chunk of runs can be made anywhere.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from rbi.core.validity import finite
from rbi.errors import shown

MAX_RUNS = 10**8
"""Most runs one sweep may plan (a row is about 150 bytes of CSV)."""


def _finite(what: str, *values: float) -> None:
    """ValueError ``WHAT must be finite numbers`` unless every value is one."""
    if not all(finite(v) for v in values):
        raise ValueError(f"{what}must be finite numbers (got {', '.join(shown(v) for v in values)})")


@dataclass(frozen=True)
class Grid(Sequence):
    """``count`` evenly spaced values from ``start`` to ``stop``, both included (one value,
    ``start``, when ``count`` is 1), as :func:`numpy.linspace` gives them, without holding them:
    a sweep axis of many values. ValueError unless start and stop are finite and
    1 <= count <= 1e8."""

    start: float
    stop: float
    count: int

    def __post_init__(self) -> None:
        _finite("start and stop ", self.start, self.stop)
        if not (finite(self.count) and float(self.count).is_integer() and self.count >= 1):
            raise ValueError(f"count must be a whole number, at least 1 (got {shown(self.count)})")
        if self.count > MAX_RUNS:
            raise ValueError(f"count must be at most {MAX_RUNS:.0e} (got {shown(self.count)})")

    def values(self) -> np.ndarray:
        return (
            np.linspace(self.start, self.stop, int(self.count)) if self.count > 1 else np.array([self.start])
        )

    def __len__(self) -> int:
        return int(self.count)

    def __getitem__(self, index):  # type: ignore[override]
        return self.values()[index]

    def __iter__(self):
        return iter(self.values().tolist())

    def __array__(self, dtype=None, copy=None) -> np.ndarray:
        return self.values() if dtype is None else self.values().astype(dtype)


@dataclass(frozen=True)
class Normal:
    """A value drawn per run from the normal distribution of ``mean`` and standard deviation
    ``sd`` (>= 0); ValueError otherwise."""

    mean: float
    sd: float

    def __post_init__(self) -> None:
        _finite("normal(mean, sd): ", self.mean, self.sd)
        if self.sd < 0:
            raise ValueError(
                f"normal(mean, sd): the standard deviation must not be negative (got {self.sd!r})"
            )

    def draw(self, rng: np.random.Generator) -> float:
        return float(rng.normal(self.mean, self.sd))


@dataclass(frozen=True)
class Uniform:
    """A value drawn per run uniformly between ``low`` and ``high`` (low <= high); ValueError
    otherwise."""

    low: float
    high: float

    def __post_init__(self) -> None:
        _finite("uniform(low, high): ", self.low, self.high)
        if self.high < self.low:
            raise ValueError(
                f"uniform(low, high): needs low <= high (got {shown(self.low)}, {shown(self.high)})"
            )
        if not math.isfinite(self.high - self.low):
            raise ValueError(
                "uniform(low, high): high - low overflows a double; the range must be narrower than "
                f"{np.finfo(float).max:.3g}"
            )

    def draw(self, rng: np.random.Generator) -> float:
        return float(rng.uniform(self.low, self.high))


@dataclass(frozen=True)
class GridAxis:
    """One axis of the grid: its name (a column) and its values (a :class:`Grid` or a tuple)."""

    name: str
    grid: Grid | tuple[float, ...]

    @property
    def count(self) -> int:
        return len(self.grid)

    def values(self) -> np.ndarray:
        return self.grid.values() if isinstance(self.grid, Grid) else np.array(self.grid, dtype=float)

    def largest(self) -> float:
        """The largest magnitude on the axis."""
        if isinstance(self.grid, Grid):
            return max(abs(self.grid.start), abs(self.grid.stop))
        return max(abs(v) for v in self.grid)


@dataclass(frozen=True)
class Draw:
    """An axis drawn at random per run: its name and its distribution."""

    name: str
    distribution: Normal | Uniform

    def largest(self) -> float:
        d = self.distribution
        return abs(d.mean) + 3 * d.sd if isinstance(d, Normal) else max(abs(d.low), abs(d.high))


def axis_of(name: str, value: Any) -> GridAxis | Draw:
    """The axis ``name`` takes ``value``: a number (one value), a sequence of numbers or a
    :class:`Grid` (the grid's values), a :class:`Normal` or :class:`Uniform` (a draw per run).
    TypeError or ValueError saying what is wrong."""
    if isinstance(value, (Normal, Uniform)):
        return Draw(name, value)
    if isinstance(value, Grid):
        return GridAxis(name, value)
    if isinstance(value, (str, bytes, bool)):
        raise TypeError(f"expected a number, a sequence of numbers, Grid, Normal or Uniform (got {value!r})")
    if isinstance(value, numbers.Real):
        if not finite(value):
            raise ValueError(f"the values must be finite numbers (got {shown(value, 60)})")
        values: tuple[float, ...] = (float(value),)
    else:
        _refuse_habits(value)
        try:
            array = np.asarray(value, dtype=float)
            values = tuple(float(v) for v in array.ravel())
        except OverflowError:
            raise ValueError(f"the values must be finite numbers (got {shown(value, 60)})") from None
        except (TypeError, ValueError):
            raise TypeError(
                f"expected a number, a sequence of numbers, Grid, Normal or Uniform (got {value!r:.60})"
            ) from None
        if array.ndim > 1:
            raise ValueError(
                f"expected one value per run, a flat sequence (got an array of shape {array.shape})"
            )
        if not values:
            raise ValueError("expected at least one value (got none)")
        if len(values) > MAX_RUNS:
            raise ValueError(f"more than {MAX_RUNS:.0e} values")
    if not all(math.isfinite(v) for v in values):
        raise ValueError(f"the values must be finite numbers (got {value!r:.60})")
    return GridAxis(name, values)


def _refuse_habits(value: Any) -> None:
    """Refuse values that would run other than meant: a tuple of three numbers whose last is a
    whole number (the command line's ``START:STOP:COUNT`` habit: ``(100, 300, 3)`` would run
    spins 100, 300 and 3; a list or an array of them runs as given) and booleans (``[True]``
    would run 1.0)."""
    if isinstance(value, tuple) and len(value) == 3 and all(isinstance(v, numbers.Real) for v in value):
        start, stop, count = value
        if float(count).is_integer() and not any(isinstance(v, bool) for v in value):
            count = int(count)
            raise ValueError(
                f"{value!r} looks like START, STOP, COUNT (the command line's {start}:{stop}:{count}): "
                f"give rbi.Grid({start}, {stop}, {count}) (or numpy.linspace({start}, {stop}, {count})) "
                f"for {count} values from {start} to {stop}, or the list {list(value)} for these three"
            )
    if isinstance(value, (list, tuple)) and any(isinstance(v, (bool, np.bool_)) for v in value):
        raise TypeError(f"the values must be numbers, not True or False (got {value!r:.60})")
    if isinstance(value, np.ndarray) and value.dtype == bool:
        raise TypeError("the values must be numbers, not an array of bool")


def axis_record(axis: GridAxis | Draw) -> list[Any]:
    """An axis as plain JSON data (what makes two sweeps the same, for ``--resume``)."""
    if isinstance(axis, Draw):
        d = axis.distribution
        return ["normal", d.mean, d.sd] if isinstance(d, Normal) else ["uniform", d.low, d.high]
    if isinstance(axis.grid, Grid):
        return ["grid", axis.grid.start, axis.grid.stop, axis.grid.count]
    return list(axis.grid)


@dataclass(frozen=True)
class Plan:
    """Every run of a sweep. axes: spin, tilt and each varied path (grid or draw), in column
    order; runs: draws per grid point (1 without Monte Carlo); seed of the draws."""

    axes: tuple[GridAxis | Draw, ...]
    runs: int = 1
    seed: int = 0

    @property
    def names(self) -> list[str]:
        return [a.name for a in self.axes]

    @property
    def size(self) -> int:
        return math.prod(a.count for a in self.axes if isinstance(a, GridAxis)) * self.runs

    def values(self, start: int, stop: int) -> np.ndarray:
        """The values of runs ``start .. stop-1``: an array (stop - start, len(axes))."""
        index = np.arange(start, stop, dtype=np.int64)
        out = np.empty((index.size, len(self.axes)))
        radix = index // self.runs  # the grid point of each run
        grid_columns = [i for i, a in enumerate(self.axes) if isinstance(a, GridAxis)]
        for column in reversed(grid_columns):  # the last grid axis changes fastest
            axis = self.axes[column]
            radix, position = np.divmod(radix, axis.count)
            out[:, column] = axis.values()[position]
        for column, axis in enumerate(self.axes):
            if isinstance(axis, Draw):
                out[:, column] = [self._draw(axis, column, int(i)) for i in index]
        return out

    def _draw(self, axis: Draw, column: int, run: int) -> float:
        """Run ``run``'s value of a drawn axis: from a generator seeded by (seed, run, column),
        so a value does not depend on which chunk computes it."""
        rng = np.random.default_rng([self.seed, run, column])
        return axis.distribution.draw(rng)
