"""Every file pybullet_data and gymnasium ship, through rbi.audit (convex mesh inertia where a mesh is not
closed); agreement with MuJoCo (bodies, totals) and Pinocchio (totals). Run from the repository root:
.venv/bin/python docs/scripts/audit_shipped_files.py (about 5 minutes). The numbers in docs/audit.md come from it."""

import collections
import glob
import json
import os
import sys
import time

import numpy as np

sys.path.insert(0, ".")
import gymnasium
import mujoco
import pybullet_data
from tests.robot.test_shipped_files import _pinocchio_totals, _relative_error

from rbi.errors import InputError
from rbi.robot import audit

P = pybullet_data.getDataPath()
G = os.path.join(os.path.dirname(gymnasium.__file__), "envs", "mujoco", "assets")
files = (
    sorted(glob.glob(P + "/**/*.urdf", recursive=True))
    + sorted(glob.glob(P + "/**/*.sdf", recursive=True))
    + sorted(glob.glob(G + "/*.xml"))
)
t = time.time()
stats = collections.Counter()
flags = collections.Counter()
refused = []
links = 0
audited = 0
pin_worst = (0, None)
mj_worst = (0, None)
flagged_files = collections.Counter()
for f in files:
    try:
        try:
            r = audit(f)
        except InputError as e:
            if "--mesh-inertia convex" not in str(e):
                raise
            r = audit(f, mesh_inertia="convex")
            stats["convex"] += 1
    except InputError as e:
        refused.append(str(e).replace(P + "/", ""))
        continue
    audited += 1
    links += len(r.links)
    for l in r.links:
        for fl in l.flags:
            flags[(fl.code, fl.level)] += 1
    if any(l.has_error for l in r.links):
        flagged_files[f.endswith(".xml") and "mjcf" or ("random" in f and "random" or "other")] += 1
    if f.endswith(".urdf"):
        exp = _pinocchio_totals(f)
        if exp is not None and exp[0] > 0:
            T = r.total
            e = max(
                abs(T.mass - exp[0]) / exp[0],
                _relative_error(T.center_of_mass, exp[1]) if np.max(np.abs(exp[1])) > 1e-14 else 0,
                _relative_error(T.inertia_about_com, exp[2]),
            )
            stats["pinocchio"] += 1
            if e > pin_worst[0]:
                pin_worst = (e, f.replace(P + "/", ""))
    if f.startswith(G):
        m = mujoco.MjModel.from_xml_path(f)
        d = mujoco.MjData(m)
        mujoco.mj_forward(m, d)
        for l in r.links:
            b = m.body(l.link.name).id if l.link.name else l.link.index + 1
            R = np.zeros(9)
            mujoco.mju_quat2Mat(R, m.body_iquat[b])
            R = R.reshape(3, 3)
            ref = R @ np.diag(m.body_inertia[b]) @ R.T
            e = max(
                abs(l.declared.mass - m.body_mass[b]) / m.body_mass[b],
                np.max(np.abs(l.declared.center_of_mass - m.body_ipos[b]))
                / max(np.max(np.abs(m.body_ipos[b])), 1e-300),
                _relative_error(l.declared.inertia_about_com, ref),
            )
            if e > mj_worst[0]:
                mj_worst = (e, os.path.basename(f) + ":" + str(l.link.name))
            stats["mujoco bodies"] += 1
        e = max(
            abs(r.total.mass - m.body_subtreemass[0]) / m.body_subtreemass[0],
            _relative_error(r.total.center_of_mass, d.subtree_com[0]),
        )
        if e > mj_worst[0]:
            mj_worst = (e, os.path.basename(f) + ": total")
print(
    json.dumps(
        {
            "files": len(files),
            "audited": audited,
            "links": links,
            "convex fallback": stats["convex"],
            "refused": refused,
            "flags": {f"{c}/{l}": n for (c, l), n in sorted(flags.items())},
            "files with errors": flagged_files,
            "pinocchio files": stats["pinocchio"],
            "pinocchio worst": pin_worst,
            "mujoco bodies": stats["mujoco bodies"],
            "mujoco worst": mj_worst,
            "seconds": time.time() - t,
        },
        indent=1,
        default=str,
    )
)
