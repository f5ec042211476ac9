"""File -> YAML (safe) -> validated models -> core inputs, with every error as one line."""

from __future__ import annotations

import contextvars
import json
import os
import re
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any, get_args

import yaml
from pydantic import BaseModel, ValidationError

from rbi.files.safe import InputFileRefused, read_input_file
from rbi.formats.paths import spec_relative_file
from rbi.memory import collector_paused
from rbi.spec.errors import InputError, describe_error, format_location, part_label
from rbi.spec.expect import Expect
from rbi.spec.models import SHAPE_MODELS, AssemblyPart, BodySpec
from rbi.spec.plus_minus import first_part_uncertain, named_plus_minus, split_uncertain, with_sub_assemblies
from rbi.spec.translate import body_from_spec
from rbi.spec.uncertain import MAX_STEPPED, stepped_size
from rbi.spec.yaml_reader import MAX_DEPTH, YamlProblem, read_document

if TYPE_CHECKING:
    from rbi.spec.translate import LoadedBody


MAX_SPEC_BYTES = 64 * 1024 * 1024
"""Largest spec file rbi reads (64 MiB: about 8 × 10⁵ parts written one a line)."""


def read_spec_file(path: str | Path) -> tuple[str, bytes]:
    """The text of a spec file, and the bytes it was read from (the file's, exactly);
    :class:`InputError` for a missing, non-regular, over-large, empty, binary or non-UTF-8
    file. Refused before reading: a device, a FIFO, a directory or a file larger than
    :data:`MAX_SPEC_BYTES` (a file that grows while read is cut there too). A UTF-8 byte-order
    mark at the start is dropped from the text."""
    path = str(path)
    try:
        data = read_input_file(path, MAX_SPEC_BYTES, "spec", hint=": put many points in a point_cloud file")
    except InputFileRefused as exc:
        raise InputError(f"{path}: {exc}") from None
    return _spec_text(data, path), data


def _spec_text(data: bytes, label: str) -> str:
    """Bytes read from a spec (file or standard input) as text, held to the rules of
    :func:`read_spec_file`."""
    if len(data) > MAX_SPEC_BYTES:
        raise InputError(f"{label}: too large (more than {MAX_SPEC_BYTES:,} bytes)")
    if b"\x00" in data:
        raise InputError(f"{label}: not a text file (binary data)")
    try:
        return check_spec_text(data.decode("utf-8"), label)
    except UnicodeDecodeError as exc:
        raise InputError(f"{label}: not UTF-8 text (byte {exc.start})") from None


STDIN = "-"
"""The FILE that means standard input."""

STDIN_LABEL = "<stdin>"
"""How messages and outputs name a spec read from standard input."""


def spec_label(path: str | Path) -> str:
    """How messages name the spec at ``path``: the path as given, ``<stdin>`` for ``-``."""
    path = str(path)
    return STDIN_LABEL if path == STDIN else path


def read_stdin_text() -> str:
    """One spec (YAML or JSON) read from standard input to its end, held to the rules of
    :func:`read_spec_file` (UTF-8, at most :data:`MAX_SPEC_BYTES`, not empty), named
    ``<stdin>`` in messages."""

    stream = getattr(sys.stdin, "buffer", None)
    try:
        if stream is not None:
            data = stream.read(MAX_SPEC_BYTES + 1)
        else:  # a text stream without bytes underneath (a test's StringIO)
            data = (sys.stdin.read(MAX_SPEC_BYTES + 1) if sys.stdin is not None else "").encode("utf-8")
    except OSError as exc:
        raise InputError(f"{STDIN_LABEL}: cannot read: {exc.strerror or exc}") from None
    return _spec_text(data, STDIN_LABEL)


def read_yaml(path: str | Path) -> Any:
    """Parsed YAML of a spec file (see :mod:`rbi.spec.yaml_reader` for what is refused);
    :class:`InputError` for a missing, empty, binary or malformed file. ``-`` reads standard
    input (named ``<stdin>`` in messages)."""
    return read_spec(path)[0]


def read_spec(path: str | Path) -> tuple[Any, bytes | None]:
    """:func:`read_yaml`'s parsed YAML, and the bytes it was parsed from: the file's, exactly as
    read (None for standard input). What the spec's file held is read once: a sweep hashes these
    bytes for ``--resume`` (:meth:`rbi.sweeps.study.Study.store_settings`), never the file again,
    which may have changed since."""
    path = str(path)
    if path == STDIN:
        return parse_spec_text(read_stdin_text(), STDIN_LABEL), None
    text, data = read_spec_file(path)
    return parse_spec_text(text, path), data


def check_spec_text(text: str, label: str) -> str:
    """Spec text given in memory (not read from a file) held to the rules of
    :func:`read_spec_file`: not empty, no NUL, at most :data:`MAX_SPEC_BYTES`; a leading
    byte-order mark dropped. ``label`` names it in messages (``<stdin>``, ``<string>``)."""
    if len(text) > MAX_SPEC_BYTES:
        raise InputError(f"{label}: too large (more than {MAX_SPEC_BYTES:,} bytes)")
    if "\x00" in text:
        raise InputError(f"{label}: not a text file (binary data)")
    if text.startswith("\ufeff"):
        text = text[1:]
    if not text.strip():
        raise InputError(f"{label}: file is empty")
    return text


_SURROGATE_ESCAPE = re.compile(r"\\[uU]0{0,4}[dD][89a-fA-F][0-9a-fA-F]{2}")
"""``\\ud800`` … ``\\udfff`` written as an escape: the only way a lone surrogate gets into a spec."""


MAX_VALUES = MAX_SPEC_BYTES // 2
"""Most values (written out: a list shared by two places counts twice) a spec given as data may
hold: as many as a spec file of :data:`MAX_SPEC_BYTES` could write (``0,`` each)."""


def check_plain_data(value: Any, path: str, most: int | None = MAX_VALUES) -> None:
    """InputError naming ``path`` unless ``value`` (a parsed spec, or a dict given to the API) is
    plain data a spec could be: lists and mappings nested at most :data:`MAX_DEPTH` levels and
    never holding themselves, at most ``most`` values written out (None: no bound), no string
    (key or value) holding a lone surrogate (half of a UTF-16 pair, not a character, that no
    terminal, JSON or CSV writer can encode). A list or mapping shared by several places is
    looked into once."""

    sizes: dict[int, int] = {}  # values written out, of each list or mapping looked into
    inside: set[int] = set()  # the lists and mappings being looked into, outermost first

    def size(item: Any, at: str, depth: int) -> int:
        if isinstance(item, str):
            _refuse_lone_surrogate(item, path, at)
            return 1
        if not isinstance(item, (dict, list, tuple)):
            return 1
        if id(item) in sizes:
            return sizes[id(item)]
        if id(item) in inside or depth >= MAX_DEPTH:
            where = at if len(at) <= 60 else at[:57] + "..."
            raise InputError(
                f"{path}: {where or 'the spec'}: nests deeper than {MAX_DEPTH} levels or holds itself"
            )
        inside.add(id(item))
        total = 1
        if isinstance(item, dict):
            for key, child in item.items():
                total += size(key, at, depth + 1) + size(child, f"{at}.{key}" if at else str(key), depth + 1)
        else:
            total += sum(size(child, f"{at}[{i}]", depth + 1) for i, child in enumerate(item))
        inside.discard(id(item))
        sizes[id(item)] = total
        if most is not None and total > most:
            raise InputError(f"{path}: holds more than {most:,} values (as many as a spec file may have)")
        return total

    size(value, "", 0)


def _refuse_lone_surrogate(text: str, path: str, at: str) -> None:
    bad = next((c for c in text if "\ud800" <= c <= "\udfff"), None)
    if bad is not None:
        raise InputError(
            f"{path}: {at.encode('ascii', 'backslashreplace').decode() or 'text'}: holds a lone "
            f"surrogate \\u{ord(bad):04x} (half of a UTF-16 pair, not a character); write the "
            "character itself or its full pair"
        )


def parse_spec_text(text: str, path: str) -> Any:
    """Parsed YAML (or JSON) of spec text, messages prefixed with ``path``; a lone surrogate
    written as an escape is refused naming its field."""
    parsed = _parse_spec_text(text, path)
    if _SURROGATE_ESCAPE.search(text):
        check_plain_data(parsed, path, most=None)
    return parsed


def _parse_spec_text(text: str, path: str) -> Any:
    with collector_paused():
        parsed = _parse_json(text)
        if parsed is not _NOT_JSON:
            return parsed
        try:
            return read_document(text)
        except YamlProblem as exc:
            shown = 6  # path components named; a deeply nested one is cut
            part_label, field_path = format_location(exc.where[:shown], None)
            if len(exc.where) > shown:
                field_path = [(field_path[0] if field_path else "") + "..."]
            where = ([part_label] if part_label else []) + field_path
            raise InputError(
                ": ".join([path, *where, f"line {exc.line}, column {exc.column}: {exc.problem}"])
            ) from None
        except yaml.MarkedYAMLError as exc:
            mark = exc.problem_mark or exc.context_mark
            where = f"line {mark.line + 1}, column {mark.column + 1}: " if mark else ""
            problem = exc.problem or exc.context or "invalid YAML"
            raise InputError(f"{path}: YAML syntax error: {where}{problem}") from None
        except yaml.YAMLError as exc:
            raise InputError(f"{path}: YAML syntax error: {str(exc)[:200]}") from None


_NOT_JSON = object()


def _parse_json(text: str) -> Any:
    """Fast path for a spec written as one JSON object (valid YAML too, and what a program that
    writes 10⁵ parts emits): the json module reads it about 100 times faster than PyYAML.
    Anything else — YAML, invalid JSON, a key given twice, nesting deeper than the YAML
    reader's limit, an integer too long for Python — returns ``_NOT_JSON`` and goes to the YAML
    reader, which reports the problem with its line and column."""
    if not text.lstrip().startswith("{"):
        return _NOT_JSON

    def unique(pairs):
        keys = [k for k, _ in pairs]
        if len(set(keys)) != len(keys):
            raise ValueError("duplicate key")
        return dict(pairs)

    try:
        parsed = json.loads(text, object_pairs_hook=unique)
    except (ValueError, RecursionError):
        return _NOT_JSON
    return parsed if _depth_within(parsed, MAX_DEPTH) else _NOT_JSON


def _depth_within(value: Any, limit: int) -> bool:
    """Whether lists and dicts in ``value`` nest at most ``limit`` levels (level by level, no
    recursion)."""
    level = [value] if isinstance(value, (dict, list)) else []
    for _ in range(limit):
        if not level:
            return True
        level = [
            child
            for item in level
            for child in (item.values() if isinstance(item, dict) else item)
            if isinstance(child, (dict, list))
        ]
    return not level


def validation_messages(path: str, raw: Any) -> tuple[Any, list[str]]:
    """Validate parsed YAML: the spec model (or None) and one message line per problem."""
    spec, problems, _ = _validated(path, raw)
    return spec, problems


def _validated(path: str, raw: Any) -> tuple[Any, list[str], tuple[str | None, str | None]]:
    """:func:`validation_messages`, and the part label and field path of the first problem (as
    the messages order them; None where not known), for :class:`InputError`'s ``part`` and
    ``field``."""

    if raw is None:
        return None, [f"{path}: file holds no YAML document"], (None, None)
    if not isinstance(raw, dict):
        message = f"{path}: must be a mapping with a `parts` list at the top level (got {type(raw).__name__})"
        return None, [message], (None, None)
    spec, failed = None, None
    try:
        if not first_part_uncertain(raw):  # else read out of its ± first: each ± would fail here, slowly
            with collector_paused():
                spec = BodySpec.model_validate(raw)
            if not named_plus_minus(spec):  # a name is text: a ± there reads without error
                return spec, [], (None, None)
    except ValidationError as exc:
        failed = exc
    try:
        split = split_uncertain(raw, path)  # only when the plain reading fails: no cost without ±
    except InputError as bad:
        return None, [str(bad)], (bad.part, bad.field)
    if split is not None:
        spec, problems, first = _validated(path, split.plain)
        if spec is not None:
            spec._uncertain = split.inputs
        return spec, problems, first
    if failed is not None:
        errors = sorted(failed.errors(include_url=False), key=lambda e: e["type"] != "extra_forbidden")
        part_label, field_path = format_location(tuple(errors[0]["loc"]), raw)
        first = (part_label or None, ".".join(field_path) or None)
        return None, [_format_error(path, err, raw) for err in errors], first
    return spec, [], (None, None)


def _format_error(path: str, error: dict[str, Any], raw: Any) -> str:
    part_label, field_path = format_location(tuple(error["loc"]), raw)
    message = describe_error(error, _known_fields(error["loc"], raw))
    pieces = [path] + ([part_label] if part_label else []) + field_path + [message]
    return ": ".join(pieces)


def _known_fields(loc: tuple[Any, ...], raw: Any) -> list[str]:
    """Field names valid where an unknown field was found (for 'did you mean'): walk the
    models along the error's location, through optional, list and union-of-shape fields."""

    model: Any = BodySpec
    for item in loc[:-1]:
        if isinstance(item, int):
            continue
        if model is BodySpec and item in ("parts", "expect"):  # fields read by a validator of their own
            model = SHAPE_MODELS if item == "parts" else Expect
            continue
        if model is SHAPE_MODELS:
            model = SHAPE_MODELS.get(item)
        elif isinstance(model, type) and issubclass(model, BaseModel) and item in model.model_fields:
            model = _model_inside(model.model_fields[item].annotation)
        else:
            model = None
        if model is None:
            return []
    return list(model.model_fields) if isinstance(model, type) and issubclass(model, BaseModel) else []


def _model_inside(annotation: Any) -> Any:
    """The pydantic model an annotation holds (``X | None``, ``list[X]``, ``Annotated[X, ...]``)."""

    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in get_args(annotation):
        found = _model_inside(arg)
        if found is not None:
            return found
    return None


def spec_from_raw(path: str, raw: Any):
    """Validate already parsed YAML (``raw``) of the spec file ``path``; raises
    :class:`InputError` with the first problem."""
    spec, problems, (part, field) = _validated(path, raw)
    if problems:
        named = STDIN if path == STDIN_LABEL else path
        more = ""
        if len(problems) > 1:  # a spec given as text or a dict (rbi.load) has no file to validate
            how = "" if named.startswith("<") else f"; `rbi validate {named}` lists all"
            more = f" (+{len(problems) - 1} more{how})"
        raise InputError(problems[0] + more, file=path, part=part, field=field)
    read_assemblies(spec, path)
    return spec


MAX_NESTING = 10
"""Most sub-assembly files nested inside one another below a spec."""

_nesting: contextvars.ContextVar[tuple[tuple[tuple[str, str], ...], dict]] = contextvars.ContextVar(
    "rbi_nesting",
    default=((), {}),
)
"""The spec files being read, outermost first (real path, name in messages), and the
sub-assemblies read so far below the outermost, by real path (each file is read once)."""


def read_assemblies(spec: BodySpec, path: str) -> None:
    """Read the file of each ``shape: assembly`` part of a validated spec as a spec of its own
    (beside the spec, as its other files: :func:`rbi.formats.paths.spec_relative_file`),
    translated in its own units, for :func:`rbi.spec.translate.assembly_element`; InputError
    naming the part for a file that cannot be read or is not a valid spec, a file that holds
    itself (naming the chain of files) or nesting deeper than :data:`MAX_NESTING` files."""
    chain, read = _nesting.get()
    chain, read = chain or ((os.path.realpath(path), path),), read if chain else {}
    for i, part in enumerate(spec.parts):
        if not isinstance(part, AssemblyPart):
            continue
        where = f"{path}: {part_label(i, part)}: file: {part.file}"
        file = spec_relative_file(path, part.file, where)
        label, real = str(file), os.path.realpath(file)
        if real in (each for each, _ in chain):
            names = " -> ".join([name for _, name in chain] + [label])
            raise InputError(f"{where}: a cycle of sub-assemblies: {names}")
        if len(chain) > MAX_NESTING:
            raise InputError(f"{where}: sub-assemblies nest deeper than {MAX_NESTING} files")
        if real not in read:
            token = _nesting.set(((*chain, (real, label)), read))
            try:
                read[real] = body_from_spec(spec_from_raw(label, read_yaml(file)), label)
            except InputError as exc:
                raise InputError(f"{where}: {str(exc).removeprefix(label + ': ')}") from None
            finally:
                _nesting.reset(token)
        part._loaded, inputs = read[real], len(read[real].spec._uncertain)
        if inputs and stepped_size(part, MAX_STEPPED // inputs) * inputs > MAX_STEPPED:
            raise InputError(
                f"{where}: {inputs:,} numbers with ± inside, each stepped through all its parts: more "
                f"than {MAX_STEPPED:,} parts to build for their uncertainty"
            )
    spec._uncertain = with_sub_assemblies(spec)  # a sub-assembly's ± are the body's too


def load_body(path: str | Path) -> LoadedBody:
    """Read, validate and translate a spec file (``-``: standard input, whose files are looked
    for in the current folder) into core inputs."""

    path = str(path)
    return body_from_raw(read_yaml(path), spec_label(path))


def body_from_raw(raw: Any, path: str) -> LoadedBody:
    """Validate and translate already parsed YAML (a dict shaped like the spec) named ``path``
    in messages; files it names are looked for beside ``path``."""

    with collector_paused():
        return body_from_spec(spec_from_raw(path, raw), path)


def file_problems(path: str, packages: dict[str, list[Path]] | None = None) -> list[str]:
    """Every problem found in one spec file, one line each (empty when it is valid):
    unreadable or malformed YAML, each field the models refuse, then the first problem met
    while building the body (an unphysical custom inertia, a hole removing too much). A robot
    file (URDF, SDF, MJCF) gives every link whose inertia is not physical; ``packages`` (see
    :func:`rbi.formats.robot_paths.parse_package_paths`) finds its ``package://`` meshes."""
    from rbi.formats.robot_files import is_robot_file, robot_file_problems  # `rbi inertia` would load it too

    if is_robot_file(path):
        return robot_file_problems(path, packages)
    try:
        raw = read_yaml(path)
    except InputError as exc:
        return [str(exc)]
    spec, problems = validation_messages(spec_label(path), raw)
    if problems:
        return problems
    try:
        read_assemblies(spec, spec_label(path))
        body_from_spec(spec, spec_label(path))
    except InputError as exc:
        return [str(exc)]
    return []
