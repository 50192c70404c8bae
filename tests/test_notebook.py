"""docs/examples/gyro.ipynb runs from top to bottom in a real IPython kernel (nbclient), and
its outputs hold the rendered worked answer."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat", reason="nbformat is in the dev extra")
nbclient = pytest.importorskip("nbclient", reason="nbclient is in the dev extra")
pytest.importorskip("ipykernel", reason="ipykernel is in the dev extra")

NOTEBOOK = Path(__file__).resolve().parent.parent / "docs" / "examples" / "gyro.ipynb"


@pytest.mark.slow
def test_notebook_runs_and_shows_the_worked_answer(tmp_path):
    nb = nbformat.read(NOTEBOOK, as_version=4)
    env_backend = os.environ.get("MPLBACKEND")
    os.environ.pop("MPLBACKEND", None)  # the kernel's inline backend returns plots as PNG
    try:
        client = nbclient.NotebookClient(nb, timeout=120, kernel_name="python3",
                                         resources={"metadata": {"path": str(NOTEBOOK.parent)}})
        client.execute()
    finally:
        if env_backend is None:
            os.environ.pop("MPLBACKEND", None)
        else:
            os.environ["MPLBACKEND"] = env_backend
    outputs = [o for cell in nb.cells if cell.cell_type == "code" for o in cell.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    html = [o["data"]["text/html"] for o in outputs if "text/html" in o.get("data", {})]
    worked = html[0]
    assert "<math" in worked and "Steady precession" in worked and "533.5" in worked
    assert "<th scope=\"col\">as given</th>" in worked          # the Given table
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert "45.13 rpm (slow), 533.5 rpm (fast)" in text
    assert "given.spinn -> unknown key" in text
    assert any("precession_slow" in h for h in html)             # the sweep's table
    assert any("image/png" in o.get("data", {}) for o in outputs)   # the sweep's plot
    assert any("PASS" in h for h in html)                        # the check report
    nbformat.write(nb, tmp_path / "executed.ipynb")
    # the outputs stored in the repository are today's (`make examples` stores them): the
    # docs site shows them as they are, and they name no folder of the machine that ran them
    stored = nbformat.read(NOTEBOOK, as_version=4)
    assert _shown(stored) == _shown(nb), "docs/examples/gyro.ipynb is stale: make examples"
    assert "/work/" not in NOTEBOOK.read_text() and "/home/" not in NOTEBOOK.read_text()


def _shown(nb) -> list:  # type: ignore[no-untyped-def]
    """Each code cell's outputs as a reader sees them, but for the pictures' bytes."""
    return [[(o.output_type, o.get("text"),
              {k: v for k, v in o.get("data", {}).items() if not k.startswith("image/")})
             for o in cell.outputs] for cell in nb.cells if cell.cell_type == "code"]
