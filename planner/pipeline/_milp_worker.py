"""Worker process of the station optimiser.

``python -m planner.pipeline._milp_worker IN.npz OUT.npz``:

Reads the cover matrix, demand, upper bound and time limit, solves the integer program with
``scipy.optimize.milp`` and writes status, solution and dual bound. Run by
:func:`planner.pipeline.optimise.solve_cover` for large models, so that the parent can stop
it at the time limit (HiGHS does not check the clock during presolve).
"""

from __future__ import annotations

import sys

import numpy as np
import scipy.sparse as sp


def main(src: str, dst: str) -> None:
    from planner.pipeline.optimise import _milp

    with np.load(src) as d:
        a = sp.csr_matrix((d["data"], d["indices"], d["indptr"]), shape=tuple(d["shape"]))
        status, message, x, dual = _milp(a, d["dem"], int(d["upper"]), float(d["time_limit"]))
    np.savez(
        dst,
        status=status,
        message=str(message),
        x=np.array([]) if x is None else x,
        has_x=x is not None,
        dual=np.nan if dual is None else float(dual),
    )


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
