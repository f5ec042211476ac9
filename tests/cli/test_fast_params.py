"""rbi.cli.fast_params gives what typer's own (pydantic) coercion gives, value and type, or
hands the value to it; and rbi's commands then build no pydantic TypeAdapter."""

from __future__ import annotations

import subprocess
import sys

import pytest
from typer._click.exceptions import BadParameter
from typer._coercion import build_runtime_param

from rbi.cli import fast_params
from rbi.cli.app import COMMANDS, _build_command

INPUTS = [
    "0",
    "7",
    "-3",
    "+12",
    "007",
    "1.5",
    "-2.25e3",
    "1e-3",
    "1E5",
    ".5",
    "5.",
    "inf",
    "-inf",
    "nan",
    " 4",
    "4 ",
    "1_000",
    "0x10",
    "",
    "abc",
    "table",
    "json",
    "JSON",
    "csv",
    "y",
    "x",
    "true",
    "1.0",
    "1e400",
    "-0",
    "00.5",
    "1.5e-400",
    "-0.0",
    "123456789012345678901234567890",
    "+0",
    "1e",
    "--1",
]


def _descriptors():
    seen = {}
    for name in COMMANDS:
        for param in _build_command(name).params:
            descriptor = getattr(param, "type_descriptor", None)
            if descriptor is not None and descriptor.file_annotation is None:
                seen.setdefault(repr(descriptor.annotation), (param, descriptor))
    return list(seen.values())


def _outcome(runtime, value, param):
    try:
        result = runtime._coerce_value(value, param=param, ctx=None)
    except BadParameter as exc:
        return ("error", str(exc))
    return ("ok", type(result), result if result == result else "nan")


@pytest.mark.parametrize(
    "param,descriptor", _descriptors(), ids=lambda x: getattr(x, "name", None) or repr(x)
)
def test_same_result_as_typer(param, descriptor):
    typer_param = build_runtime_param(descriptor)
    fast = fast_params._runtime_param_class()(
        annotation=descriptor.annotation, parameter_info=descriptor.parameter_info, descriptor=descriptor
    )
    values = INPUTS + [3, 2.5, True, False, ["a", "b"], ("a",), []]
    for value in values:
        assert _outcome(fast, value, param) == _outcome(typer_param, value, param), (
            descriptor.annotation,
            value,
        )


def test_fast_path_taken_for_plain_values():
    # the fast path answers these without building typer's adapter
    assert fast_params._fast(float, None, "2.5", None) == (True, 2.5)
    assert fast_params._fast(int, None, "-40", None) == (True, -40)
    assert fast_params._fast(float, None, "nan", None) == (False, None)
    assert fast_params._fast(int, None, "1.0", None) == (False, None)


def test_commands_build_no_type_adapter(tmp_path):
    code = (
        "import sys; from rbi.cli.app import main\n"
        "sys.argv = ['rbi', 'inertia', sys.argv[1], '--format', 'json']\n"
        "try:\n    main()\nexcept SystemExit:\n    pass\n"
        "print('ADAPTERS', 'typer._adapters' in sys.modules, file=sys.stderr)\n"
    )
    import pathlib

    top = pathlib.Path(__file__).resolve().parents[2] / "bodies" / "top.yaml"
    proc = subprocess.run([sys.executable, "-c", code, str(top)], capture_output=True, text=True)
    assert '"mass"' in proc.stdout
    assert "ADAPTERS False" in proc.stderr
