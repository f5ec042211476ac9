"""MJCF reading (rbi.formats.mjcf): refusals name the file they are about."""

from __future__ import annotations

import pytest

from tests.conftest import one_line_exit_2, run_rbi_inprocess


@pytest.mark.parametrize("included", [False, True])
@pytest.mark.parametrize("command", ["audit", "import"])
def test_a_class_no_default_defines_is_one_line_naming_the_file(tmp_path, command, included):
    """Found: a geom with class="ghost" (no <default class="ghost">) was refused as 'rbi: line
    1: class 'ghost': no <default class> of that name': no file named (and, inside an included
    file, its path ran into the word 'line'). Now the file, the element and its line."""
    geom = '<body name="a"><joint/><geom class="ghost" size="0.1"/></body>'
    if included:
        (tmp_path / "part.xml").write_text(f"<mujoco><worldbody>{geom}</worldbody></mujoco>")
        geom, named = '<include file="part.xml"/>', "part.xml: <geom> (line 1)"
    else:
        named = "robot.xml: <geom> (line 1)"
    path = tmp_path / "robot.xml"
    path.write_text(
        f"<mujoco><worldbody/>{geom}</mujoco>"
        if included
        else f"<mujoco><worldbody>{geom}</worldbody></mujoco>"
    )
    one_line_exit_2(
        run_rbi_inprocess(command, path), named + ": class 'ghost': no <default class> of that name"
    )
