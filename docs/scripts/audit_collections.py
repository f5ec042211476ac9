"""Every robot file of the collections the test extra installs, through rbi.audit as a new user
runs it (default options, the collection's package folder given with --package-path): files
found, audited as given (exit 0 or 1), refused by reason, crashed; totals against Pinocchio
(URDF) and MuJoCo (MJCF), joint holding torques against Pinocchio's computeGeneralizedGravity
and MuJoCo's qfrc_bias. Run from the repository root:

    .venv/bin/python docs/scripts/audit_collections.py [COLLECTION ...] > survey.json

(some minutes: example-robot-data's Collada meshes dominate). docs/audit.md quotes its numbers.
"""

from __future__ import annotations

import collections
import glob
import json
import os
import re
import site
import sys
import time

import numpy as np

sys.path.insert(0, ".")
from tests.robot.test_shipped_files import _pinocchio_totals, _relative_error  # noqa: E402

from rbi.errors import InputError  # noqa: E402
from rbi.robot import audit  # noqa: E402


def _site(*parts: str) -> str:
    for entry in site.getsitepackages():
        candidate = os.path.join(entry, *parts)
        if os.path.exists(candidate):
            return candidate
    return ""


def collections_to_survey() -> dict[str, tuple[list[str], dict[str, str]]]:
    """name → (robot files, package paths)."""
    erd = _site("cmeel.prefix", "share", "example-robot-data", "robots")
    icub = os.path.normpath(os.path.join(site.getsitepackages()[0], "..", "..", "..", "share", "iCub"))
    gim = _site("gym_ignition_models")
    dmc = _site("dm_control")
    found = {
        "example-robot-data (URDF, Collada)": (
            sorted(glob.glob(erd + "/**/*.urdf", recursive=True)) if erd else [],
            {"example-robot-data": os.path.dirname(erd)} if erd else {},
        ),
        "icub-models (URDF)": (
            sorted(glob.glob(icub + "/robots/**/*.urdf", recursive=True)),
            {"iCub": icub},
        ),
        "gym-ignition-models (URDF, SDF)": (
            sorted(
                glob.glob(gim + "/**/*.urdf", recursive=True) + glob.glob(gim + "/**/*.sdf", recursive=True)
            )
            if gim
            else [],
            {os.path.basename(d): d for d in glob.glob(gim + "/*") if os.path.isdir(d)} if gim else {},
        ),
        "dm_control (MJCF, mesh geoms)": (
            sorted(
                f
                for f in glob.glob(dmc + "/**/*.xml", recursive=True)
                if b"<mujoco" in open(f, "rb").read(4096) and b"<worldbody" in open(f, "rb").read()
            )
            if dmc
            else [],
            {},
        ),
        "drake (SDF, URDF)": (_drake_files(), {}),
    }
    return found


def _drake_files() -> list[str]:
    share = _site("pydrake", "share", "drake")
    if not share:
        return []
    return sorted(
        glob.glob(share + "/**/*.sdf", recursive=True) + glob.glob(share + "/**/*.urdf", recursive=True)
    )


def _drake(path: str, report) -> float | None:
    """Worst relative difference of the totals against Drake's MultibodyPlant (None: Drake refuses)."""
    from tests.robot.test_drake_collection import _drake_totals

    try:
        mass, com, inertia = _drake_totals(path, report.total.frame.removeprefix("root link "))
    except Exception:  # noqa: BLE001 - Drake refuses some files rbi reads
        return None
    return max(
        abs(report.total.mass - mass) / mass,
        _relative_error(report.total.center_of_mass, com) if np.max(np.abs(com)) > 1e-14 else 0,
        _relative_error(report.total.inertia_about_com, inertia),
    )


def _reason(message: str) -> str:
    """A refusal's reason in a few words (the part after the file, link and field)."""
    text = message.split(": ")[-1] if ": " in message else message
    text = re.sub(r"'[^']*'|\"[^\"]*\"|[-+]?\d[\d.e+-]*", "…", text)
    return text[:90]


def _pinocchio_torques(path: str, report) -> float | None:
    try:
        import pinocchio as pin

        model = pin.buildModelFromUrdf(path)
    except Exception:  # noqa: BLE001 - Pinocchio refuses some files rbi reads
        return None
    data = model.createData()
    g = pin.computeGeneralizedGravity(model, data, pin.neutral(model))
    ours = {each.name: each.torque for each in report.joints}
    scale = max(float(np.max(np.abs(g))) if len(g) else 0.0, 1e-9)  # relative, or absolute below 1e-9 N·m
    worst = 0.0
    for jid in range(1, model.njoints):
        if model.joints[jid].nv == 1 and model.names[jid] in ours:
            worst = max(worst, abs(ours[model.names[jid]] - g[model.joints[jid].idx_v]) / scale)
    return worst


def _mujoco(path: str, report) -> tuple[float, float] | None:
    """(worst relative difference of total mass and CoM, of joint torques) against MuJoCo."""
    import mujoco

    try:
        model = mujoco.MjModel.from_xml_path(path)
    except Exception:  # noqa: BLE001
        return None
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    mass = float(model.body_subtreemass[0])
    totals = max(
        abs(report.total.mass - mass) / mass if mass else 0.0,
        _relative_error(report.total.center_of_mass, data.subtree_com[0]) if mass else 0.0,
    )
    ours = {each.name: each.torque for each in report.joints}
    scale = max(float(np.max(np.abs(data.qfrc_bias))) if model.nv else 0.0, 1e-9)
    torques = 0.0
    for j in range(model.njnt):
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, j)
        if model.jnt_type[j] in (2, 3) and name in ours:
            torques = max(torques, abs(ours[name] - data.qfrc_bias[model.jnt_dofadr[j]]) / scale)
    return totals, torques


def survey(files: list[str], packages: dict[str, str]) -> dict:
    counts = collections.Counter()
    refused = collections.Counter()
    crashed = []
    worst = {"pinocchio totals": 0.0, "pinocchio torques": 0.0, "mujoco totals": 0.0, "mujoco torques": 0.0}
    compared = collections.Counter()
    start = time.perf_counter()
    for path in files:
        try:
            report = audit(path, package_paths=packages)
        except InputError as exc:
            refused[_reason(str(exc))] += 1
            continue
        except Exception as exc:  # noqa: BLE001 - a crash is what this survey counts
            crashed.append(f"{os.path.basename(path)}: {type(exc).__name__}: {exc}"[:200])
            continue
        counts[f"exit {report.exit_code}"] += 1
        if path.endswith(".urdf") and "pydrake" not in path:
            expected = _pinocchio_totals(path)
            if expected is not None and expected[0] > 0:
                total = report.total
                error = max(
                    abs(total.mass - expected[0]) / expected[0],
                    _relative_error(total.center_of_mass, expected[1])
                    if np.max(np.abs(expected[1])) > 1e-14
                    else 0,
                    _relative_error(total.inertia_about_com, expected[2]),
                )
                worst["pinocchio totals"] = max(worst["pinocchio totals"], error)
                compared["pinocchio totals"] += 1
            torques = _pinocchio_torques(path, report)
            if torques is not None:
                worst["pinocchio torques"] = max(worst["pinocchio torques"], torques)
                compared["pinocchio torques"] += 1
        if "pydrake" in path:
            found = _drake(path, report)
            if found is not None:
                worst["drake totals"] = max(worst.get("drake totals", 0.0), found)
                compared["drake totals"] += 1
        elif path.endswith(".xml"):
            found = _mujoco(path, report)
            if found is not None:
                worst["mujoco totals"] = max(worst["mujoco totals"], found[0])
                worst["mujoco torques"] = max(worst["mujoco torques"], found[1])
                compared["mujoco"] += 1
    return {
        "files": len(files),
        "audited": sum(counts.values()),
        "exit codes": dict(counts),
        "refused": sum(refused.values()),
        "refused by reason": dict(refused.most_common()),
        "crashed": len(crashed),
        "crashes": crashed,
        "compared": dict(compared),
        "worst relative difference": worst,
        "seconds": round(time.perf_counter() - start, 1),
    }


def main(names: list[str]) -> None:
    results = {}
    for name, (files, packages) in collections_to_survey().items():
        if names and not any(n in name for n in names):
            continue
        results[name] = survey(files, packages)
        print(name, json.dumps(results[name]), file=sys.stderr, flush=True)
    print(json.dumps(results, indent=1, default=str))


if __name__ == "__main__":
    main(sys.argv[1:])
