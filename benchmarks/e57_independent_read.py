"""The rehearsal's E57 read by an independent library (run by hand, in a venv of its own).

    python -m venv /tmp/e57venv && /tmp/e57venv/bin/pip install e57 matplotlib numpy
    .venv/bin/planner rehearse --out /tmp/rh --beams-per-station 200000
    /tmp/e57venv/bin/python benchmarks/e57_independent_read.py /tmp/rh/scans.e57

``e57`` (PyPI; the Rust ``e57`` crate's binding) shares no code with ``pye57``
(libE57Format), which wrote the file: it reads every scan, applies each scan's pose and
returns the points in the site's CRS. The picture (benchmarks/e57_independent_read.png) is
a plan view and an elevation of what it read, grey by intensity.
"""

import re
import sys

import e57
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt

path = sys.argv[1] if len(sys.argv) > 1 else "/tmp/rh/scans.e57"
pc = e57.read_points(path)
xml = e57.raw_xml(path)
pts, grey = np.asarray(pc.points), np.asarray(pc.intensity).ravel()
names = re.findall(r'<name type="String"><!\[CDATA\[(S\d+)\]\]>', xml)
fig, ax = plt.subplots(1, 2, figsize=(16, 7.5))
up = pts[:, 2] > 0.3
ax[0].scatter(pts[up, 0], pts[up, 1], s=0.05, c=grey[up], cmap="gray")
ax[0].set_aspect("equal")
ax[0].set_title(
    f"{path.rsplit('/', 1)[-1]} read by the independent 'e57' library: {len(pts):,} points, "
    f"{len(names)} scans ({names[0]}–{names[-1]})\nplan view, points above 0.3 m, grey = intensity"
)
ax[0].set_xlabel("E [m]")
ax[0].set_ylabel("N [m]")
ax[1].scatter(pts[:, 0], pts[:, 2], s=0.02, c=grey, cmap="gray")
ax[1].set_title("elevation looking north (E against height)")
ax[1].set_xlabel("E [m]")
ax[1].set_ylabel("H [m]")
ax[1].set_ylim(-1, 25)
fig.tight_layout()
fig.savefig("benchmarks/e57_independent_read.png", dpi=80)
print(f"{len(pts):,} points in {len(names)} scans: {', '.join(names)}")
