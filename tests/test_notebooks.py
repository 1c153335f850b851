"""Every notebook in notebooks/ runs without error (nbclient, one kernel for all, its names
cleared before each), and is committed clean."""

from __future__ import annotations

from pathlib import Path

import pytest

NOTEBOOKS = sorted((Path(__file__).resolve().parent.parent / "notebooks").glob("*.ipynb"))


def test_there_are_notebooks():
    names = {p.name for p in NOTEBOOKS}
    assert {
        "station_planner.ipynb",
        "accuracy_explorer.ipynb",
        "targets.ipynb",
        "report.ipynb",
    } <= names


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_is_committed_without_outputs(path):
    import nbformat  # here, not at collection (a second even without jsonschema's IRI grammar)

    nb = nbformat.read(path, as_version=4)
    for cell in nb.cells:
        if cell.cell_type == "code":
            assert not cell.outputs and cell.execution_count is None


@pytest.fixture(scope="module")
def kernel(tmp_path_factory):
    """One Python kernel for the module's notebooks (a kernel's start and the package's
    imports are most of a small notebook's run), its names cleared before each."""
    from jupyter_client.manager import KernelManager

    km = KernelManager(kernel_name="python3")
    km.start_kernel(cwd=str(tmp_path_factory.mktemp("notebooks")))
    yield km
    km.shutdown_kernel(now=True)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_executes(path, kernel):
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.read(path, as_version=4)
    reset = nbformat.v4.new_code_cell("%reset -f")  # nothing left of the notebook before
    nb.cells.insert(0, reset)
    # a hang (a lost kernel message) fails in minutes, not at CI's limit
    client = NotebookClient(nb, km=kernel, timeout=240, startup_timeout=120)
    try:
        client.execute()
    finally:
        if client.kc is not None:
            client.kc.stop_channels()
    nb.cells.remove(reset)
    errors = [
        o for c in nb.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"
    ]
    assert not errors
    shown = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert shown  # the notebook displays something
