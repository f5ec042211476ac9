"""The xacro sandbox cannot be escaped (issue 38): an expression that reaches Python objects
(a comprehension past xacro's ``__`` check, a lambda, a format string, dunder text built at run
time, ``python.vars``) is refused, exit 2 and one line, and nothing outside the robot's folder
is read, changed or deleted; ordinary xacro (properties, macros, math, YAML, conditionals)
expands as xacro expands it."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from tests.conftest import run_rbi_inprocess

pytest.importorskip("xacro")

WRAP_CLOSE = (
    "[c for x in [()] for c in x.__class__.__base__.__subclasses__() if c.__name__ == '_wrap_close'][0]"
)
DUNDER = "'_' * 2"

PAYLOADS = {
    "comprehension": "${[c.__init__.__globals__ for x in [()] for c in x.__class__.__base__.__subclasses__()"
    " if c.__name__ == '_wrap_close'][0]['remove']('CANARY')}",
    "import": "${[c.__init__.__globals__['__builtins__']['__import__']('os').remove('CANARY') for x in [()]"
    " for c in x.__class__.__base__.__subclasses__() if c.__name__ == '_wrap_close']}",
    "lambda": "${(lambda: " + WRAP_CLOSE + ".__init__.__globals__['truncate']('CANARY', 0))()}",
    "class": "${[().__class__.__base__.__subclasses__() for x in [1]]}",
    "environ": "${[(g['sys'].modules['__main__'].__dict__.update(allow=True), g['__builtins__']['open']("
    "'/proc/%d/environ' % g['getppid']()).read().replace(chr(0), ' '))[1] for x in [()] for c in"
    " x.__class__.__base__.__subclasses__() if c.__name__ == '_wrap_close' for g in [c.__init__.__globals__]"
    " for chr in [g['__builtins__']['chr']]][0]}",
    "format": "${'{0.__globals__[os].environ}'.format(xacro.load_yaml)}",
    "built_dunder": "${python.vars(python.type)["
    + DUNDER
    + " + 'subclasses' + "
    + DUNDER
    + "](python.type(()).mro()[1])}",
    "joined_dunder": "${python.vars(python.type)[''.join(['_', '_', 'subclasses', '_', '_'])](python.type(()).mro()[1])}",
    "values": "${python.type(()).mro()}",
    "property_alias": None,  # below: python.vars kept in a property, called by another name
}


def _robot(folder, expression: str) -> str:
    path = folder / "robot.urdf.xacro"
    if expression is None:
        body = '<xacro:property name="v" value="${python.vars}"/><link name="${v(python)}"/>'
    else:
        body = f'<link name="{expression}"/>'
    path.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">{body}</robot>')
    return str(path)


@pytest.mark.parametrize("name", list(PAYLOADS))
def test_expressions_that_reach_python_objects_are_refused(tmp_path, name):
    """Before: the comprehension deleted the canary (exit 0), the lambda truncated it, 'environ'
    printed the parent's environment, the format string and python.vars printed module globals
    and class lists (exit 0 or 1)."""
    canary = tmp_path / "canary.txt"
    canary.write_text("still here\n")
    folder = tmp_path / "robot"
    folder.mkdir()
    expression = PAYLOADS[name]
    if expression is not None:
        expression = expression.replace("CANARY", str(canary)).replace('"', "&quot;")
    path = _robot(folder, expression)
    env = dict(os.environ, RBI_SECRET_TOKEN="s3cr3t-value")
    proc = subprocess.run(
        [sys.executable, "-m", "rbi", "audit", path, "--format", "json"],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
    )
    assert proc.returncode == 2, (proc.returncode, proc.stdout[:300], proc.stderr[:300])
    assert proc.stdout == "" and len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    assert "Traceback" not in proc.stderr and "s3cr3t" not in proc.stderr
    assert canary.read_text() == "still here\n"


LEGITIMATE = """<?xml version="1.0"?>
<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="cfg" value="${xacro.load_yaml('arm.yaml')}"/>
  <xacro:property name="m" value="${cfg['mass'] * 2}"/>
  <xacro:property name="names" value="${['a', 'b']}"/>
  <xacro:arg name="prefix" default="left_"/>
  <xacro:macro name="box_link" params="name mass:=1.0 size:=^|0.1 *origin">
    <link name="$(arg prefix)${name}">
      <inertial><xacro:insert_block name="origin"/><mass value="${mass}"/>
        <inertia ixx="${mass * (size**2 + size**2) / 12}" iyy="${mass / 6 * size**2}" izz="${mass * size * size / 6}"
                 ixy="0" ixz="0" iyz="0"/></inertial>
    </link>
  </xacro:macro>
  <xacro:box_link name="${names[0]}" mass="${m}"><origin xyz="0 0 ${-pi / 4 if m > 1 else 0}"/></xacro:box_link>
  <xacro:box_link name="${cfg.arm.name + '_' + str(len(names))}" size="${radians(90) / 10}">
    <origin rpy="${math.atan2(1, 1)} 0 ${python.abs(-1.5) + min(1, 2) + python.sorted([3, 1])[0]}" xyz="0 0 0"/>
  </xacro:box_link>
  <xacro:if value="${m == 4 and not (cfg['mass'] != 2)}">
    <link name="${'c' if 'x' in 'xyz' else 'd'}${'_%d' % int(m)}"/>
  </xacro:if>
  <xacro:unless value="${xacro.tokenize('1 2 3')[-1] == '3'}"><link name="never"/></xacro:unless>
  <joint name="j" type="fixed"><parent link="left_a"/><child link="c_4"/><origin xyz="${' '.join(['1', '2', '3'])}"/></joint>
</robot>
"""


def test_ordinary_xacro_expands_as_xacro_expands_it(tmp_path):
    (tmp_path / "arm.yaml").write_text("mass: 2\narm: {name: fore}\n")
    path = tmp_path / "arm.urdf.xacro"
    path.write_text(LEGITIMATE)
    from rbi.formats.xacro_sandbox import expand_xacro

    expanded, includes = expand_xacro(str(path))
    plain = subprocess.run(
        [
            sys.executable,
            "-c",
            "import sys, xacro; print(xacro.process_file(sys.argv[1]).toxml())",
            str(path),
        ],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        check=True,
    )
    assert expanded.decode() == plain.stdout.rstrip("\n")
    assert b'name="c_4"' in expanded and b"never" not in expanded
    assert includes == [str((tmp_path / "arm.yaml").resolve())]


def test_the_test_collections_xacro_files_expand_as_before():
    """example-robot-data's hector quadrotor (the .xacro files installed with the test extras)."""
    root = os.path.join(sys.prefix, "lib")
    found = [os.path.join(d, f) for d, _, fs in os.walk(root) for f in fs if f.endswith(".xacro")]
    if not found:
        pytest.skip("no .xacro file in the installed collections")
    from rbi.errors import InputError
    from rbi.formats.xacro_sandbox import expand_xacro

    expanded = 0
    for path in found:
        plain = subprocess.run(
            [sys.executable, "-c", "import sys, xacro; print(xacro.process_file(sys.argv[1]).toxml())", path],
            capture_output=True,
            text=True,
        )
        if plain.returncode:  # a file of macros only: xacro refuses it too
            with pytest.raises(InputError):
                expand_xacro(path)
            continue
        assert expand_xacro(path)[0].decode() == plain.stdout.rstrip("\n")
        expanded += 1
    assert expanded


def test_a_refusal_names_the_file(tmp_path):
    path = _robot(tmp_path, "${[x for x in [1]]}")
    proc = run_rbi_inprocess("audit", path)
    assert proc.returncode == 2 and path in proc.stderr and "comprehension" in proc.stderr, proc.stderr


def _landlock() -> bool:
    import ctypes

    return sys.platform == "linux" and ctypes.CDLL(None).syscall(444, None, 0, 1) >= 1


@pytest.mark.skipif(not _landlock(), reason="this kernel has no Landlock")
@pytest.mark.parametrize("name", ["comprehension", "lambda", "environ"])
def test_the_kernel_stops_an_expression_that_got_past_the_check(tmp_path, monkeypatch, name):
    """The second wall alone: with the expression check switched off, the payload runs in the
    child and reaches os, but Landlock refuses the delete, the truncation and the reading of
    /proc/PPID/environ; the canary survives."""
    from rbi.errors import InputError
    from rbi.formats import xacro_sandbox

    child = xacro_sandbox._CHILD.replace("why = refusal(args[0])", "why = None")  # the hook's walls down
    child = child.replace('"os.remove", "os.rmdir", "os.rename", "os.truncate", ', "")
    child = child.replace("if not allow and not real.startswith(inside):", "if False:")
    assert child.count("why = None") == child.count("if False:") == 1
    monkeypatch.setattr(xacro_sandbox, "_CHILD", child)
    canary = tmp_path / "canary.txt"
    canary.write_text("still here\n")
    folder = tmp_path / "robot"
    folder.mkdir()
    path = _robot(folder, PAYLOADS[name].replace("CANARY", str(canary)).replace('"', "&quot;"))
    monkeypatch.setenv("RBI_SECRET_TOKEN", "s3cr3t-value")
    with pytest.raises(InputError) as refused:
        xacro_sandbox.expand_xacro(path)
    message = str(refused.value)
    assert "s3cr3t" not in message and "Errno 13] Permission denied" in message, message
    assert canary.read_text() == "still here\n"
