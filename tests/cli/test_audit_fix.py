"""`rbi audit --fix --out FILE`'s table output: what it says it wrote and what it could not fix."""

from __future__ import annotations

from tests.conftest import run_rbi_inprocess

NEGATIVE_MOMENTS = """<?xml version="1.0"?>
<robot name="r">
  <link name="base">
    <inertial><mass value="2"/><inertia ixx="-1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.1 0.05"/></geometry></collision>
  </link>
  <link name="arm">
    <inertial><mass value="2"/><inertia ixx="-1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="j" type="fixed"><parent link="base"/><child link="arm"/></joint>
</robot>
"""


def test_the_fixed_copys_path_is_printed_escaped(tmp_path, monkeypatch):
    # `rbi audit r.urdf --fix --out $'f\x1b[31mX.urdf'` wrote the ESC byte to stdout ('wrote
    # f\x1b[31mX.urdf'); the path is shown escaped, as in rbi's messages
    monkeypatch.chdir(tmp_path)
    (tmp_path / "r.urdf").write_text(NEGATIVE_MOMENTS)
    proc = run_rbi_inprocess("audit", "r.urdf", "--fix", "--out", "f\x1b[31mX.urdf")
    assert proc.returncode == 1, proc.stderr  # arm has no geometry: it stays unfixed
    assert (tmp_path / "f\x1b[31mX.urdf").exists()
    assert "\x1b" not in proc.stdout
    lines = proc.stdout.splitlines()
    assert "--fix: 1 inertial(s) replaced; wrote f\\x1b[31mX.urdf" in lines
    assert lines[-1].startswith("--fix: link[1] (arm): not fixed: it has no geometry")
