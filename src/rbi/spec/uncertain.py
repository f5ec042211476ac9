"""What the uncertainty of a spec's inputs (the numbers it writes with ±, read out by
:mod:`rbi.spec.plus_minus`) does to the body: sensitivities, the law of propagation, Monte
Carlo and the budget (JCGM 100 and 101).

:func:`part_stack` evaluates one part's mass properties for many values of its uncertain inputs
at once (Monte Carlo draws, or the complex steps of the sensitivities): the common shapes as
whole arrays (:data:`rbi.spec.translate.BUILDERS`), a mesh's or STEP file's solid as scalings
of one built solid, a sub-assembly as its own body's stack (:func:`rows_at`), each turned and
patterned as a stack; the other shapes part by part through the same translation.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

from rbi.core.mass import MassProperties
from rbi.core.rotation import radians, unit_vector, without_rounding_noise
from rbi.core.uncertainty import (
    axis_uncertainty_deg,
    body_derivatives,
    body_stack,
    combined,
    coverage_factor,
    principal_derivatives,
    scale_safe,
    shortest_interval,
    squares_lost,
    validated,
)
from rbi.errors import ArgumentError, InputError, literal
from rbi.spec import models
from rbi.spec.errors import part_label
from rbi.spec.fields import MATRIX_ROWS
from rbi.spec.geometry import part_count
from rbi.spec.pattern import copy_motions
from rbi.spec.plus_minus import UncertainInput
from rbi.spec.translate import BUILDERS, Columns, given_by, part_element, plain_part, rotation_matrix
from rbi.spec.units import LENGTH_UNITS_IN_M, MASS_UNITS_IN_KG, convert_body

NO_PLUS_MINUS = "the spec writes no number with ± (VALUE ± U): every uncertainty is zero"
"""The budget's warning for a spec without ± (its every u is zero, which is not an answer)."""


def _replaced(node: Any, steps: tuple[Any, ...], value: Any) -> Any:
    """``node`` (a part model, a sub-model or a list of numbers) with the number at ``steps``
    replaced by ``value``; nothing validated again (the value is a nearby or drawn number)."""
    head, rest = steps[0], steps[1:]
    if head == "inertia" and isinstance(node, models.CustomPart):
        # a number of a custom part's symmetric matrix (a component or an entry): both its places
        named = ((i, r.index(rest[0])) for i, r in enumerate(MATRIX_ROWS) if rest[0] in r)
        i, j = rest if len(rest) == 2 else next(named)
        matrix = [list(row) for row in node.inertia]
        matrix[i][j] = matrix[j][i] = value
        return node.model_copy(update={"inertia": matrix})
    if rest:
        value = _replaced(node[head] if isinstance(node, list) else getattr(node, head), rest, value)
    if isinstance(node, list):
        return [*node[:head], value, *node[head + 1 :]]
    return node.model_copy(update={head: value})


PLACED = (models.MeshPart, models.StepPart, models.AssemblyPart)
"""Parts whose solid is a file's (mesh, STEP, sub-assembly), turned about its origin, moved to
``position``."""


MAX_STEPPED = 1_000_000
"""Most parts the sensitivities to one sub-assembly's ± inputs may build: each input is stepped
through the whole sub-assembly (about 0.5 kB and 1 µs a part), so this bounds their product."""


def stepped_size(part: models.AssemblyPart, most: int) -> int:
    """How many parts one stepped evaluation of the sub-assembly ``part`` builds (its copies,
    its parts, and so on for each of its sub-assemblies that has ± inputs), counted until past
    ``most``."""
    total = part.pattern.count if part.pattern is not None else 1
    for each in part._loaded.spec.parts:
        uncertain = isinstance(each, models.AssemblyPart) and each._loaded.spec._uncertain
        total += 1 + (stepped_size(each, most) if uncertain else 0)
        if total > most:
            break
    return total


def _with(part: Any, inputs: list[UncertainInput], row: np.ndarray) -> Any:
    """``part`` with each of its ``inputs`` set to its value in ``row``."""
    for each, value in zip(inputs, row):
        part = _replaced(part, each.steps, value.item())
    return part


def _each_row(part: Any, field: str, inputs: list[UncertainInput], values: np.ndarray, make: Any) -> Any:
    """``make(part.field)``, or one a row of ``values`` (stacked) when inputs are in the field."""
    mine = [k for k, x in enumerate(inputs) if x.steps[0] == field]
    if not mine:
        return make(getattr(part, field, None))
    chosen = [inputs[k] for k in mine]
    return np.array([make(getattr(_with(part, chosen, row[mine]), field)) for row in values])


def _turns(part: Any, inputs: list[UncertainInput], values: np.ndarray) -> np.ndarray | None:
    """The part's rotation matrix, or one a row of ``values`` (n, 3, 3) when inputs are in it:
    an axis and angle as one stack (:func:`rbi.core.rotation.axis_angle_matrix`'s arithmetic),
    the other forms row by row."""
    mine = {x.steps[1:]: values[:, k] for k, x in enumerate(inputs) if x.steps[0] == "rotation"}
    if not mine or part.rotation.angle_deg is None:
        return _each_row(part, "rotation", inputs, values, rotation_matrix)
    columns = Columns([part.rotation], np.zeros(len(values), int), mine)
    u, angle = unit_vector(columns.column("axis")), radians(columns.column("angle_deg"))[:, None, None]
    K = np.cross(u[:, None, :], np.eye(3)).transpose(0, 2, 1)  # u × (each axis): the cross-product matrix
    c, s = np.cos(angle), np.sin(angle)
    return without_rounding_noise(c * np.eye(3) + s * K + (1.0 - c) * u[:, :, None] * u[:, None, :])


def _motions(pattern: Any) -> np.ndarray:
    """(copies, 3, 4): ``[R | t]`` of each copy of a pattern (:func:`rbi.spec.pattern.copy_motions`)."""
    return np.array([np.column_stack((R, t)) for R, t in copy_motions(pattern)])


Stack = tuple[np.ndarray, np.ndarray, np.ndarray]
"""Masses, centres of mass and inertias about them of a stack of parts or bodies."""
SEPARATE = ("rotation", "pattern", "file")
"""Where a part's inputs are not columns of its closed form (:class:`rbi.spec.translate.Columns`)."""


def _file_stack(
    loaded: Any, part: Any, inputs: list, values: np.ndarray, columns: Columns, expand: bool
) -> Stack:
    """A mesh's, STEP file's or sub-assembly's mass, centre of mass and inertia for each row of
    ``values``, (n, 1) (a sub-assembly's parts (n, r) when ``expand``), in its own axes about
    its origin: a sub-assembly's body from its own inputs (rescaled to its measured ``mass``),
    a file's solid as the scalings of one built solid (mass ∝ density and scale³, or scale² for
    a shell; centre ∝ scale; inertia ∝ mass·scale²)."""
    units = loaded.spec.units
    if isinstance(part, models.AssemblyPart):
        inner = convert_body(part._loaded, units.length, units.mass)
        rows = rows_at(inner, values[:, [k for k, x in enumerate(inputs) if x.steps[0] == "file"]], expand)
        mass, com, inertia = (
            rows if expand else (x[:, None] for x in body_stack(*rows, inner.props.center_of_mass))
        )
        factor = 1.0 if part.mass is None else columns.column("mass") / mass.sum(axis=1)
        return mass * np.reshape(factor, (-1, 1)), com, inertia * np.reshape(factor, (-1, 1, 1, 1))
    unit = (
        {"mass": 1.0} if part.mass is not None else {} if isinstance(part.density, str) else {"density": 1.0}
    )
    at_origin = {"rotation": None, "pattern": None, "position": [0.0] * 3}
    base = part_element(part.model_copy(update=at_origin | unit), units, loaded.path)
    scale = (
        columns.column("scale") / part.scale if isinstance(part, models.MeshPart) else np.ones(len(columns))
    )
    if part.mass is not None:
        mass = columns.column("mass")
    else:
        power = 2 if getattr(part, "inertia", None) == "shell" else 3
        mass = base.mass * scale**power * (columns.column("density") if unit else 1.0)
    per_mass = mass / base.mass * scale * scale
    com, inertia = base.center_of_mass * scale[:, None], base.inertia_about_com * per_mass[:, None, None]
    return mass[:, None], com[:, None], inertia[:, None]


@np.errstate(all="ignore")
def part_stack(
    loaded: Any, index: int | list[int], inputs: list, values: np.ndarray, expand: bool = False
) -> Stack:
    """Part ``index`` of the body ``loaded``: its mass, centre of mass and inertia about it,
    ``(n,)``, ``(n, 3)``, ``(n, 3, 3)``, file units, with its uncertain ``inputs`` set to each row
    of ``values`` ``(n, len(inputs))``, real or complex (a hole's mass and inertia negative, as
    the body counts it); with ``expand``, a sub-assembly's parts in each of its copies,
    ``(n, r, ...)``, as ``rbi parts --expand`` lists them. The shapes of
    :data:`rbi.spec.translate.BUILDERS` and the files' solids are built for all rows at once,
    then turned and patterned as one stack; the other shapes row by row. ``index`` may also list
    parts built together (:func:`part_derivatives`: one shape of ``BUILDERS`` as written, the
    same inputs, mass given alike and the same sign): each takes its share of the rows in turn,
    ``inputs`` naming the first's."""
    indices = [index] if isinstance(index, int) else index
    part, spec, n = loaded.spec.parts[indices[0]], loaded.spec, len(values)
    sign = -1.0 if getattr(part, "subtract", False) else 1.0
    if type(part) not in BUILDERS and not isinstance(part, PLACED):
        try:
            rows = MassProperties.concatenate(
                part_element(_with(part, inputs, row), spec.units, loaded.path) for row in values
            )
        except ValueError as error:  # a draw its builder refuses (a custom inertia no body has)
            raise InputError(
                f"{loaded.path}: {part_label(indices[0], part)}: Monte Carlo: a draw gives a part rbi "
                f"cannot build ({error}): the ± of its inputs are too large for it",
                file=loaded.path,
            ) from None
        return sign * rows.mass, rows.center_of_mass, sign * rows.inertia_about_com
    own = {i.steps: values[:, k] for k, i in enumerate(inputs) if i.steps[0] not in SEPARATE}
    rows = np.repeat(np.arange(len(indices)), n // len(indices))  # the part of each row
    columns = Columns([spec.parts[i] for i in indices], rows, own)
    R = _turns(part, inputs, values)
    if isinstance(part, PLACED):
        mass, com, inertia = _file_stack(loaded, part, inputs, values, columns, expand)
    else:  # a box turns about its centre
        mass, com, inertia = (x[:, None] for x in BUILDERS[type(part)](columns, spec.units))
    if R is not None:
        R = np.broadcast_to(R, (n, 3, 3))
        inertia = np.einsum("nij,nrjk,nlk->nril", R, inertia, R)
        com = np.einsum("nij,nrj->nri", R, com) if isinstance(part, PLACED) else com
    com = com + columns.column("position")[:, None] if isinstance(part, PLACED) else com
    if getattr(part, "pattern", None) is not None and part.pattern.count > 1:
        count = part.pattern.count
        motion = np.broadcast_to(_each_row(part, "pattern", inputs, values, _motions), (n, count, 3, 4))
        com = np.einsum("nkij,nrj->nkri", motion[..., :3], com) + motion[:, :, None, :, 3]
        inertia = np.einsum("nkij,nrjl,nkml->nkrim", motion[..., :3], inertia, motion[..., :3])
        mass = np.repeat(mass[:, None], count, axis=1)
    mass, com, inertia = mass.reshape(n, -1), com.reshape(n, -1, 3), inertia.reshape(n, -1, 3, 3)
    if not (expand and isinstance(part, models.AssemblyPart)):  # a pattern's copies as one part
        one = mass.shape[1] == 1
        mass, com, inertia = (
            (mass[:, 0], com[:, 0], inertia[:, 0]) if one else body_stack(mass, com, inertia, com[0, 0].real)
        )
    return sign * mass, com, sign * inertia


STEPS = np.array([1.0, 0.5, 0.25])
"""Central differences at h, h/2, h/4 combined by Richardson's extrapolation (error O(h⁶); nil
for the polynomial closed forms of degree up to 6)."""


def by_part(inputs: tuple[UncertainInput, ...]) -> dict[int, list[int]]:
    """The positions in ``inputs`` of each part's inputs, by part index."""
    found: dict[int, list[int]] = {}
    for n, each in enumerate(inputs):
        found.setdefault(each.part, []).append(n)
    return found


def _flat(stack: tuple[np.ndarray, np.ndarray, np.ndarray]) -> np.ndarray:
    """(n, [r,] 13): mass, centre of mass and inertia of a part's stack side by side."""
    mass, com, inertia = stack
    return np.concatenate([mass[..., None], com, inertia.reshape(*mass.shape, 9)], axis=-1)


def _complex_step(
    loaded: Any, index: int | list[int], group: list[UncertainInput], expand: bool = False
) -> np.ndarray | None:
    """(len(group), [r,] 13): the derivatives of part ``index``'s :func:`_flat` properties (its
    rows with ``expand``, as :func:`part_stack`) by a complex step through :func:`part_stack`
    (x + ih gives h ∂f/∂x exactly), or None when its builder cannot carry complex numbers (any
    float() on the way). ``index`` may list parts built together, ``group`` then their inputs
    in turn."""
    count = 1 if isinstance(index, int) else len(index)
    h = 1e-20 * np.array([abs(i.value) or 10.0 * i.u or 1.0 for i in group])
    each = len(group) // count  # inputs of each part
    values = np.repeat(np.array([i.value for i in group]).reshape(count, each), each, axis=0).astype(complex)
    values[np.arange(len(group)), np.tile(np.arange(each), count)] += 1j * h  # row j: input j stepped
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("error", np.exceptions.ComplexWarning)
        try:
            stack = part_stack(loaded, index, group[:each], values, expand)
        except (TypeError, ValueError, np.exceptions.ComplexWarning):
            return None
    if not any(map(np.iscomplexobj, stack)):
        return None  # the step was lost on the way
    return _flat(stack).imag / h.reshape(-1, *[1] * (stack[0].ndim))


def part_derivatives(loaded: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per uncertain input of the body ``loaded`` (a :class:`~rbi.spec.translate.LoadedBody`):
    the index of its part, the derivatives (k, 13) of that part's mass, centre of mass and
    inertia about it (:func:`_flat`, in ``loaded``'s units) with respect to the input, each part
    evaluated with its own inputs stepped (never the whole body), and whether each is only
    estimated (k,) (finite differences, ~1e-9: a part whose builder cannot carry a complex
    step)."""
    inputs, spec = loaded.spec._uncertain, loaded.spec
    k, grouped = len(inputs), by_part(inputs)
    derivative, estimated = np.zeros((k, 13)), np.zeros(k, dtype=bool)
    together: dict[Any, list[int]] = {}  # parts built together: one shape, inputs, mass kind and sign
    for index, chosen in grouped.items():
        part, steps = spec.parts[index], tuple(inputs[n].steps for n in chosen)
        # built by the whole-array closed forms of BUILDERS, which also take complex numbers
        alike = type(part) in BUILDERS and plain_part(part) and all(len(each) <= 2 for each in steps)
        key = (type(part), steps, given_by(part), getattr(part, "subtract", False)) if alike else index
        together.setdefault(key, []).append(index)
    for indices in together.values():
        chosen = [n for index in indices for n in grouped[index]]
        exact = _complex_step(loaded, indices, [inputs[n] for n in chosen])
        estimated[chosen] = exact is None
        if exact is None:  # part by part (in practice a part alone: BUILDERS carry the step)
            alone = ([inputs[n] for n in grouped[i]] for i in indices)
            exact = np.concatenate([_differences(loaded, i, group) for i, group in zip(indices, alone)])
        derivative[chosen] = exact
    return np.array([i.part for i in inputs], dtype=int), derivative / _flat_units(loaded), estimated


def _differences(loaded: Any, index: int, group: list[UncertainInput], expand: bool = False) -> np.ndarray:
    """:func:`_complex_step`'s derivatives estimated where a builder cannot carry the step: the
    part rebuilt with each input stepped by ±h, ±h/2, ±h/4 (:data:`STEPS`)."""
    nominal = np.array([i.value for i in group])
    scale = np.array([abs(i.value) or 10.0 * i.u or 1.0 for i in group])
    # powers of 2: value ± step is exact, so a part's linear dependence differentiates exactly
    h = 2.0 ** np.round(np.log2(1e-2 * scale))
    rows = np.repeat(nominal[None, :], len(group) * 6, axis=0).reshape(len(group), 3, 2, -1)
    for j in range(len(group)):
        rows[j, :, 0, j] += STEPS * h[j]
        rows[j, :, 1, j] -= STEPS * h[j]
    f = _flat(part_stack(loaded, index, group, rows.reshape(-1, len(group)), expand))
    f = f.reshape(len(group), 3, 2, *f.shape[1:])
    d = (f[:, :, 0] - f[:, :, 1]) / (2.0 * STEPS[None, :] * h[:, None]).reshape(
        len(group), 3, *[1] * (f.ndim - 3)
    )
    fine, finer = (4.0 * d[:, 1] - d[:, 0]) / 3.0, (4.0 * d[:, 2] - d[:, 1]) / 3.0
    return (16.0 * finer - fine) / 15.0


def _flat_units(loaded: Any) -> np.ndarray:
    """(13,): how many of the spec file's units make one of ``loaded``'s (1 unless it was
    converted: :func:`rbi.spec.units.convert_body`), for each of :func:`_flat`'s numbers."""
    units = loaded.spec.units
    length = LENGTH_UNITS_IN_M[loaded.length_unit] / LENGTH_UNITS_IN_M[units.length]
    mass = MASS_UNITS_IN_KG[loaded.mass_unit] / MASS_UNITS_IN_KG[units.mass]
    return np.array([mass] + [length] * 3 + [mass * length * length] * 9)


def rows_at(loaded: Any, values: np.ndarray, expand: bool = False) -> Stack:
    """The parts of ``loaded`` (its elements; each sub-assembly's parts with ``expand``, as
    :func:`rbi.spec.assembly.expanded` lists them) with its uncertain inputs set to each row of
    ``values`` (n, k), real or complex: masses (n, r), centres (n, r, 3), inertias (n, r, 3, 3),
    in its units (a hole's mass negative); the parts without inputs repeated."""
    inputs, elements, parts, n = loaded.spec._uncertain, loaded.elements, loaded.spec.parts, len(values)
    units, groups, pieces = _flat_units(loaded), by_part(inputs), []
    for index in range(len(elements)):
        chosen = groups.get(index, [])
        if chosen or (expand and index < len(parts) and isinstance(parts[index], models.AssemblyPart)):
            m, c, inertia = part_stack(loaded, index, [inputs[k] for k in chosen], values[:, chosen], expand)
            rows = (m / units[0], c / units[1], inertia / units[4])
            pieces.append([x[:, None] for x in rows] if m.ndim == 1 else list(rows))
        else:  # the part in every row
            same = elements[np.full(n, index)]
            pieces.append([same.mass[:, None], same.center_of_mass[:, None], same.inertia_about_com[:, None]])
    return tuple(np.concatenate([p[j] for p in pieces], axis=1) for j in range(3))  # type: ignore[return-value]


MONTE_CARLO_BYTES = 2 * 2**30
"""What Monte Carlo keeps in memory at most, 2 GiB (a twelfth of a 24 GiB machine, room for
the rest of it): the n × k draws of the k inputs and the n × 16 quantities drawn
(:data:`QUANTITIES`), 8 bytes each. More draws are refused before any is drawn
(:func:`monte_carlo`)."""
CHUNK_PARTS = 2**18
"""Parts built at once, draws × the body's parts (patterns copied, sub-assemblies' parts
counted: :func:`rbi.spec.geometry.part_count`): a few hundred bytes of working arrays each,
some 100 MB whatever the number of draws."""


def drawn(
    loaded: Any, n: int, rng: np.random.Generator, notes: list[str] | None = None
) -> Iterator[tuple[slice, MassProperties]]:
    """The body ``loaded`` for n draws of every uncertain input (JCGM 101 §6), in its units: the
    draws made input by input, then the bodies built from their parts (:func:`rows_at`) as
    stacks of :data:`CHUNK_PARTS` parts at a time, each chunk with its rows. Each chunk is led
    by draw 0, as one stack of all n is (a pattern's copies are summed about the first row's),
    so chunks give the numbers one stack gives, bit for bit. ``notes`` (when given) gets the
    warnings of :func:`refused_draws`, before the first chunk."""
    inputs = loaded.spec._uncertain
    draws = np.empty((n, len(inputs)))
    for j, each in enumerate(inputs):
        draws[:, j] = each.draws(rng, n)
    if notes is not None:
        notes += refused_draws(loaded, draws)
    size = max(1, CHUNK_PARTS // part_count(loaded, CHUNK_PARTS))
    for start in range(0, n, size):
        with np.errstate(all="ignore"):
            parts = rows_at(loaded, np.concatenate((draws[:1], draws[start : start + size])))
            mass, com, inertia = body_stack(*parts, loaded.props.center_of_mass)
        yield slice(start, start + size), MassProperties(mass[1:], com[1:], inertia[1:])


def refused_draws(loaded: Any, draws: np.ndarray) -> list[str]:
    """A warning for each part built draw by draw (a shape outside :data:`BUILDERS`, not a
    file's; a sub-assembly's own parts too) that some ``draws`` (n, k) make a part the spec refuses (a prism's outline that
    crosses itself, a tube's bore wider than the tube, a custom inertia no body has): how many
    draws, and the first one's reason. Each drawn part is validated as the spec's own are."""
    out, inputs = [], loaded.spec._uncertain
    for index, chosen in by_part(inputs).items():
        part, mine = loaded.spec.parts[index], [inputs[k] for k in chosen]
        if isinstance(part, models.AssemblyPart):  # its parts, each of its inputs drawn as here
            inner = np.empty((len(draws), len(part._loaded.spec._uncertain)))
            for k in (k for k in chosen if inputs[k].steps[0] == "file"):
                inner[:, inputs[k].steps[1]] = draws[:, k]
            out += refused_draws(part._loaded, inner) if inner.size else []
            continue
        if type(part) in BUILDERS or isinstance(part, PLACED):  # their fields' own limits: limit_warnings
            continue
        count, first = 0, None
        for row in draws[:, chosen]:
            try:
                type(part).model_validate(dict(_with(part, mine, row)))
            except ValueError as error:  # pydantic's ValidationError
                count, first = count + 1, first or error.errors()[0]["msg"].removeprefix("Value error, ")
        if count:
            out.append(
                f"{loaded.path}: {part_label(index, part)}: {count:,} of {len(draws):,} draws "
                f"({100 * count / len(draws):.2g}%) give a part the spec refuses (the first: {first}): "
                "Monte Carlo computes them as the formulas give them"
            )
    return out


QUANTITIES = (
    ["mass"]
    + [f"center_of_mass[{i}]" for i in range(3)]
    + [f"inertia[{i}][{j}]" for i in range(3) for j in range(3)]
    + [f"moments[{i}]" for i in range(3)]
)
"""The quantities of a body, as JSON paths of ``rbi inertia`` and ``rbi principal``: the
order of the flat vectors below."""
DEFAULT_QUANTITIES = [q for q in QUANTITIES if not (q.startswith("inertia") and q[8] > q[11])]
"""The budget's quantities unless others are asked for: the inertia's upper triangle."""


@dataclass(frozen=True)
class Linear:
    """The law of propagation on a body: ``values`` of :data:`QUANTITIES` (inertia and moments
    about ``point``), their ``sensitivities`` (q, k) to the k ``inputs`` (u (k,)), and
    ``turn`` (k, 3, 3): per input the turn of principal axis i towards axis j; ``estimated``
    (k,): the inputs whose sensitivities are finite differences, not exact."""

    inputs: tuple[UncertainInput, ...]
    u: np.ndarray
    values: np.ndarray
    sensitivities: np.ndarray
    axes: np.ndarray
    turn: np.ndarray
    estimated: np.ndarray

    @property
    def uncertainty(self) -> np.ndarray:
        """The combined standard uncertainty of each quantity (GUM 5.1.2)."""
        return combined(self.sensitivities, self.u)

    def axes_deg(self) -> list[float | None]:
        """Each principal axis's standard angular uncertainty in degrees (None: undetermined)."""
        return axis_uncertainty_deg(self.values[13:], self.uncertainty[13:], self.turn, self.u)

    def standard(self, rotation: np.ndarray | None = None) -> StandardUncertainty:
        """The :class:`StandardUncertainty` of the body's mass, centre of mass, inertia (its
        sensitivities turned into the axes of ``rotation``, when given), moments and axes."""
        u = self.uncertainty
        if rotation is None:
            inertia = u[4:13].reshape(3, 3)
        else:
            turned = np.einsum(
                "ia,qab,jb->qij", rotation, self.sensitivities[4:13].T.reshape(-1, 3, 3), rotation
            )
            inertia = np.sqrt(np.einsum("kij,k->ij", turned**2, self.u**2))
        return StandardUncertainty(
            float(u[0]), u[1:4].tolist(), inertia.tolist(), u[13:].tolist(), self.axes_deg()
        )


@dataclass(frozen=True)
class StandardUncertainty:
    """The combined standard uncertainty (GUM 5.1.2, first order) of a body's ``mass`` and
    ``center_of_mass`` and of what a result reports besides (None where it does not, and left
    out of :meth:`to_dict`): ``inertia`` (about a point), principal ``moments`` (about it),
    ``axes_deg`` (each principal axis's angular uncertainty, degrees; None for an axis of a
    pair of moments closer than 3 combined uncertainties), ``angular_momentum`` and
    ``kinetic_energy``; in the body's units."""

    mass: float
    center_of_mass: list[float]
    inertia: Any = None
    moments: Any = None
    axes_deg: Any = None
    angular_momentum: Any = None
    kinetic_energy: Any = None

    def only(self, *names: str) -> StandardUncertainty:
        """The same uncertainties, ``mass``, ``center_of_mass`` and ``names`` kept."""
        return StandardUncertainty(
            self.mass, self.center_of_mass, **{name: getattr(self, name) for name in names}
        )

    def to_dict(self) -> dict[str, Any]:
        """The ``"uncertainty"`` object of a result's JSON: the fields given, in their order."""
        return {key: value for key, value in vars(self).items() if value is not None}


def linear(loaded: Any, point: np.ndarray | None = None) -> Linear:
    """:class:`Linear` of the body ``loaded``, its inertia and moments about ``point`` (a fixed
    point of the body frame; default its centre of mass), in ``loaded``'s units."""
    inputs = loaded.spec._uncertain
    elements = loaded.elements
    masses, coms = np.array(elements.mass), np.array(elements.center_of_mass)
    props = loaded.props
    about = props.center_of_mass if point is None else np.asarray(point, dtype=float)
    inertia = props.inertia_about(about)
    part, d, estimated = part_derivatives(loaded)
    dM, dC, dJ = body_derivatives(masses, coms, part, d[:, 0], d[:, 1:4], d[:, 4:].reshape(-1, 3, 3), about)
    moments, axes, dmoments, turn = principal_derivatives(inertia, dJ)
    values = np.concatenate([[props.mass], props.center_of_mass, inertia.reshape(9), moments])
    sensitivities = np.concatenate([dM[None], dC.T, dJ.reshape(-1, 9).T, dmoments.T])
    return Linear(inputs, np.array([i.u for i in inputs]), values, sensitivities, axes, turn, estimated)


def generator(seed: int | None) -> np.random.Generator:
    """The random generator of the draws: ``seed`` gives the same draws again, None fresh ones;
    any other seed than a whole number 0 or above is an `ArgumentError` of ``seed``."""
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0):
        raise ArgumentError("seed", f"must be a whole number 0 or above (got {literal(seed)})")
    return np.random.default_rng(seed)


def monte_carlo(loaded: Any, n: int, seed: int | None, notes: list[str] | None = None) -> np.ndarray:
    """(n, q) samples of :data:`QUANTITIES` (about the centre of mass of each draw) from n draws
    of every uncertain input (JCGM 101), the bodies computed chunk by chunk (:func:`drawn`,
    which adds its warnings to ``notes``). ArgumentError of ``samples`` for more draws than
    :data:`MONTE_CARLO_BYTES` holds."""
    k = len(loaded.spec._uncertain)
    most = MONTE_CARLO_BYTES // (8 * (k + len(QUANTITIES)))
    if n > most:
        raise ArgumentError(
            "samples",
            f"must be at most {most:,} for this body: the draws of its {k} inputs with ± and their "
            f"{len(QUANTITIES)} quantities would take more than {MONTE_CARLO_BYTES // 2**30} GiB "
            f"(got {literal(n)})",
        )
    samples = np.empty((n, len(QUANTITIES)))
    for rows, body in drawn(loaded, n, generator(seed), notes):
        samples[rows, :13] = _flat((body.mass, body.center_of_mass, body.inertia_about_com))
        if not np.all(np.isfinite(samples[rows, :13])):  # eigvalsh cannot take them
            raise InputError(
                f"{loaded.path}: Monte Carlo: a drawn body's mass, centre of mass or inertia is not "
                "finite: the inputs' ± are too large for double precision",
                file=loaded.path,
            )
        with np.errstate(all="ignore"):
            samples[rows, 13:] = np.linalg.eigvalsh(body.inertia_about_com)
    return samples


class Contributions(NamedTuple):
    """Every input's part in one quantity's uncertainty, ranked largest first: ``order`` the
    inputs' positions, and their ``sensitivity`` ∂y/∂x, ``contribution`` |∂y/∂x|·u and
    ``share`` of the variance in that order. Made rows of the budget's JSON only when asked
    (:meth:`rows`): a budget of k inputs has 13 k of them."""

    inputs: tuple[UncertainInput, ...]
    order: np.ndarray
    sensitivity: np.ndarray
    contribution: np.ndarray
    share: np.ndarray

    def rows(self) -> list[dict[str, Any]]:
        """``{"input", "value", "u", "sensitivity", "contribution", "share"}`` of each input,
        JSON-ready (``-0.0`` written 0.0, as :func:`rbi.reprs.plain` writes it)."""
        inputs = [self.inputs[n] for n in self.order.tolist()]
        numbers = (a + 0.0 for a in (self.sensitivity, self.contribution, self.share))  # -0.0 + 0.0 is 0.0
        keys = ("input", "value", "u", "sensitivity", "contribution", "share")
        rows = zip(inputs, *(a.tolist() for a in numbers))
        return [dict(zip(keys, (x.path, x.value + 0.0, x.u + 0.0, s, c, f))) for x, s, c, f in rows]


METHODS = ("linear", "monte-carlo")
"""The ways :func:`budget` propagates: the law of propagation (JCGM 100) or Monte Carlo (JCGM 101)."""


def _quantities(of: str | Sequence[str] | None, method: str, samples: int, coverage: float) -> list[int]:
    """The positions in :data:`QUANTITIES` of the quantities ``of`` names (a whole vector or
    matrix stands for its entries; None: :data:`DEFAULT_QUANTITIES`), the other arguments of
    :func:`budget` checked: ArgumentError naming the parameter for one out of its range."""
    names = of if of is None or (isinstance(of, Iterable) and not isinstance(of, str)) else [of]
    if names is not None:  # a whole vector or matrix stands for its entries
        names = [q for name in names for q in ([n for n in QUANTITIES if n.startswith(f"{name}[")] or [name])]
        unknown = [q for q in names if q not in QUANTITIES]
        if unknown or not names:
            raise ArgumentError(
                "of",
                "must name quantities such as mass, center_of_mass[0], inertia[0][2], moments[1] "
                f"(got {literal(unknown[0] if unknown else names)})",
            )
    if method not in METHODS:
        raise ArgumentError("method", f"must be linear or monte-carlo (got {literal(method)})")
    if isinstance(samples, bool) or not isinstance(samples, int) or not 2 <= samples <= 10_000_000:
        raise ArgumentError(
            "samples", f"must be a whole number from 2 to 10,000,000 (got {literal(samples)})"
        )
    if isinstance(coverage, bool) or not isinstance(coverage, (int, float)) or not 0 < coverage < 1:
        raise ArgumentError(
            "coverage", f"must be a probability between 0 and 1, e.g. 0.95 (got {literal(coverage)})"
        )
    return [QUANTITIES.index(q) for q in (names or DEFAULT_QUANTITIES)]


def budget(
    loaded: Any,
    of: str | Sequence[str] | None = None,
    method: str = "linear",
    samples: int = 100_000,
    seed: int | None = None,
    coverage: float = 0.95,
) -> dict[str, Any]:
    """The uncertainty budget of ``rbi uncertainty``, as its JSON (the contract's form, each
    quantity's ``contributions`` as :class:`Contributions`; and ``estimated_sensitivities``, the
    inputs whose ∂y/∂x are not exact, when there are any), of the quantities ``of`` names
    (:func:`_quantities`, which checks the arguments)."""
    chosen, notes = _quantities(of, method, samples, coverage), [*loaded.warnings]
    drawn = monte_carlo(loaded, samples, seed, notes) if method == "monte-carlo" else None
    result = linear(loaded)
    u = result.uncertainty
    k = coverage_factor(coverage)
    quantities = []
    for q in chosen:
        value, spread = float(result.values[q]), float(u[q])
        interval = (value - k * spread, value + k * spread)
        sensitivity = result.sensitivities[q]
        part = np.abs(sensitivity) * result.u
        share = (part / spread) ** 2 if spread > 0 else np.zeros_like(part)
        ranked = np.argsort(-part, kind="stable")
        entry: dict[str, Any] = {"quantity": QUANTITIES[q], "value": value, "u": spread}
        entry["interval"] = list(interval)
        if drawn is not None:  # Monte Carlo's numbers in their place, the linear ones beside them
            y = drawn[:, q]
            symmetric = tuple(np.quantile(y, [0.5 - coverage / 2, 0.5 + coverage / 2]).tolist())
            entry["linear"] = {key: entry[key] for key in ("value", "u", "interval")}
            entry["linear"]["validated"] = validated(spread, interval, symmetric)
            spread_of_draws = scale_safe(lambda d: np.std(d, ddof=1, axis=-1), y - y[0])
            entry.update(value=float(np.mean(y)), u=float(spread_of_draws))
            entry["interval"] = list(shortest_interval(y, coverage))
        ranks = Contributions(result.inputs, ranked, sensitivity[ranked], part[ranked], share[ranked])
        entry.update(coverage=coverage, contributions=ranks)
        quantities.append(entry)
    out: dict[str, Any] = {"name": loaded.name, "units": loaded.units, "method": method}
    out.update(samples=samples if drawn is not None else None, quantities=quantities)
    if result.estimated.any():
        out["estimated_sensitivities"] = [x.path for x, e in zip(result.inputs, result.estimated) if e]
    out["warnings"] = notes + ([] if result.inputs else [NO_PLUS_MINUS])
    return out


def part_uncertainties(loaded: Any, expand: bool = False) -> MassProperties:
    """Per row of ``rbi parts`` (the elements of ``loaded`` in file order; with ``expand`` each
    sub-assembly's parts in each of its copies, as :func:`rbi.spec.assembly.expanded` lists
    them), the standard uncertainty of its ``mass``, ``center_of_mass`` and
    ``inertia_about_com`` from the inputs that move it, as one stack in ``loaded``'s units
    (zeros for a part without ±)."""
    inputs = loaded.spec._uncertain
    part, d, _ = part_derivatives(loaded)
    u = np.array([i.u for i in inputs])
    variance, largest = np.zeros((len(loaded.elements), 13)), np.zeros((len(loaded.elements), 13))
    with np.errstate(over="ignore", under="ignore"):
        np.add.at(variance, part, (d * u[:, None]) ** 2)
    np.maximum.at(largest, part, np.abs(d * u[:, None]))
    spread = np.sqrt(variance)
    lost = squares_lost(spread, largest)  # taken again as combined takes them
    for k in np.unique(np.nonzero(lost)[0]):
        spread[k] = np.where(lost[k], combined(d[part == k].T, u[part == k]), spread[k])
    rows = [v[None] for v in spread]
    for index, each in enumerate(loaded.spec.parts if expand else []):
        if isinstance(each, models.AssemblyPart):  # its parts, each moved by all its inputs
            chosen = by_part(inputs).get(index, [])
            group = [inputs[k] for k in chosen]
            if not group:  # no ± in it: its rows (as many as one evaluation gives) are exact
                found = np.zeros((0, part_stack(loaded, index, [], np.zeros((1, 0)), True)[0].shape[1], 13))
            elif (found := _complex_step(loaded, index, group, True)) is None:
                found = _differences(loaded, index, group, True)
            rows[index] = combined(np.moveaxis(found / _flat_units(loaded), 0, -1), u[chosen])
    u = np.concatenate(rows)
    return MassProperties(u[:, 0], u[:, 1:4], u[:, 4:].reshape(-1, 3, 3))


def momentum_uncertainty(
    loaded: Any, point: np.ndarray, omega: np.ndarray, velocity: np.ndarray | None
) -> StandardUncertainty:
    """The standard uncertainty of ``mass``, ``center_of_mass``, ``angular_momentum`` (about
    ``point``) and ``kinetic_energy`` at angular velocity ``omega``: turning about ``point``
    held fixed (``velocity`` None: h = I_point ω, E = ½ ωᵀ I_point ω), or with the centre of
    mass moving at ``velocity`` (h = I ω + m r × v, E = ½ ωᵀ I ω + ½ m v², r from the point)."""
    found = linear(loaded, point if velocity is None else None)
    s, k = found.sensitivities, len(found.u)
    dM, dC, dJ = s[0], s[1:4].T, s[4:13].T.reshape(k, 3, 3)
    dH, dE = dJ @ omega, 0.5 * np.einsum("i,kij,j->k", omega, dJ, omega)
    if velocity is not None:
        r = loaded.props.center_of_mass - point
        dH = dH + dM[:, None] * np.cross(r, velocity) + loaded.props.mass * np.cross(dC, velocity)
        dE = dE + 0.5 * dM * float(velocity @ velocity)
    u = found.uncertainty
    return StandardUncertainty(
        float(u[0]),
        u[1:4].tolist(),
        angular_momentum=combined(dH.T, found.u).tolist(),
        kinetic_energy=float(combined(dE, found.u)),
    )
