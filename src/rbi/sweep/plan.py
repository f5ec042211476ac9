"""The runs of a sweep: grid axes, Monte Carlo draws, and the values of run ``i``.

Grid axes are written ``START:STOP:COUNT`` (COUNT equally spaced values, both ends included)
or as one number; draws as ``normal(MEAN,SD)`` or ``uniform(LOW,HIGH)``. The runs are the
product of the grid axes in the order spin, tilt, then each ``--vary`` in the order given (the
last axis changes fastest), each repeated ``runs`` times with fresh draws; run ``i``'s values
are computed from ``i`` alone, so any chunk of runs can be made anywhere.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

import numpy as np

MAX_RUNS = 10**8
"""Most runs one sweep may plan (a row is about 150 bytes of CSV)."""

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_RANGE = re.compile(rf"^\s*({_NUMBER})\s*:\s*({_NUMBER})\s*:\s*(\d+)\s*$")
_DRAW = re.compile(rf"^\s*(normal|uniform)\s*\(\s*({_NUMBER})\s*,\s*({_NUMBER})\s*\)\s*$")


@dataclass(frozen=True)
class GridAxis:
    """``count`` values from ``start`` to ``stop`` (both included); one value when count is 1."""

    name: str
    start: float
    stop: float
    count: int

    def values(self) -> np.ndarray:
        return np.linspace(self.start, self.stop, self.count) if self.count > 1 else np.array([self.start])


@dataclass(frozen=True)
class Draw:
    """A random value per run: ``normal`` (a = mean, b = standard deviation) or ``uniform``
    (a = low, b = high)."""

    name: str
    kind: str
    a: float
    b: float


def parse_axis(name: str, text: str) -> GridAxis | Draw:
    """``START:STOP:COUNT``, a single number, ``normal(M,SD)`` or ``uniform(LO,HI)``;
    ValueError saying what is wrong."""
    text = str(text)
    if (match := _RANGE.match(text)) is not None:
        start, stop, count = float(match[1]), float(match[2]), int(match[3])
        if not (math.isfinite(start) and math.isfinite(stop)):
            raise ValueError(f"START and STOP must be finite numbers (got {text!r})")
        if count < 1:
            raise ValueError(f"COUNT must be at least 1 (got {text!r})")
        if count > MAX_RUNS:
            raise ValueError(f"COUNT must be at most {MAX_RUNS:.0e} (got {text!r})")
        return GridAxis(name, start, stop, count)
    if (match := _DRAW.match(text)) is not None:
        kind, a, b = match[1], float(match[2]), float(match[3])
        if not (math.isfinite(a) and math.isfinite(b)):
            raise ValueError(f"the parameters must be finite numbers (got {text!r})")
        if kind == "normal" and b < 0:
            raise ValueError(f"the standard deviation must not be negative (got {text!r})")
        if kind == "uniform" and b < a:
            raise ValueError(f"uniform(LOW,HIGH) needs LOW <= HIGH (got {text!r})")
        if kind == "uniform" and not math.isfinite(b - a):
            raise ValueError(
                f"uniform(LOW,HIGH): HIGH - LOW overflows a double (got {text!r}); the range must be "
                f"narrower than {np.finfo(float).max:.3g}"
            )
        return Draw(name, kind, a, b)
    try:
        value = float(text)
    except ValueError:
        raise ValueError(
            f"expected START:STOP:COUNT, a number, normal(MEAN,SD) or uniform(LOW,HIGH) (got {text[:60]!r})"
        ) from None
    if not math.isfinite(value):
        raise ValueError(f"must be a finite number (got {text!r})")
    return GridAxis(name, value, value, 1)


@dataclass(frozen=True)
class Plan:
    """Every run of a sweep. axes: spin, tilt and each varied path (grid or draw), in column
    order; runs: draws per grid point (1 without Monte Carlo); seed of the draws."""

    axes: tuple[GridAxis | Draw, ...]
    runs: int = 1
    seed: int = 0
    _grids: tuple[GridAxis, ...] = field(init=False, repr=False)

    def __post_init__(self):
        object.__setattr__(self, "_grids", tuple(a for a in self.axes if isinstance(a, GridAxis)))

    @property
    def names(self) -> list[str]:
        return [a.name for a in self.axes]

    @property
    def grid_size(self) -> int:
        return math.prod(a.count for a in self._grids)

    @property
    def size(self) -> int:
        return self.grid_size * self.runs

    def values(self, start: int, stop: int) -> np.ndarray:
        """The values of runs ``start .. stop-1``: an array (stop - start, len(axes))."""
        index = np.arange(start, stop, dtype=np.int64)
        grid_index, draw_index = np.divmod(index, self.runs)
        out = np.empty((index.size, len(self.axes)))
        radix = grid_index.copy()
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
        return float(rng.normal(axis.a, axis.b) if axis.kind == "normal" else rng.uniform(axis.a, axis.b))

    def is_grid_axis(self, name: str) -> bool:
        return any(a.name == name and a.count > 1 for a in self._grids)
