"""The example notebook runs, and leaves the folder ``sdt benchmark`` leaves from the same config.

``examples/benchmark.ipynb`` is executed in a real Jupyter kernel (nbclient),
as a user runs it, with its parameters cell followed by one that names a small
configuration file and a results folder (papermill's way of injecting
parameters). The command runs the same file into a second folder; every table
is read back and compared exactly, frame by frame, with the comparison of the
resume tests (``tests/reliability/test_bench_resume_outputs.py``): results,
per_class, confusion, per_recording, features, allocation, skipped, Table 4,
config.toml and summary.json. Left out, as there: the wall-clock ``fit_seconds``
column and summary.json's counters and timings of how the folder was filled
(computed / cached / resumed, seconds): the second run finds the first one's
features in the shared cache.
"""

from __future__ import annotations

from pathlib import Path

import nbclient
import nbformat

from ..reliability.test_bench_resume_outputs import BENCH_TABLES, BENCH_TEXTS, assert_same_outputs

NOTEBOOK = Path(__file__).resolve().parents[2] / "examples" / "benchmark.ipynb"

CONFIG = """[benchmark]
dataset_options = {{ duration = 1.5 }}
machines = ["Motor-2"]
channels = ["ch1", "ch4"]
sensors = ["wilcoxon-786b10", "adxl345"]
classifiers = ["lr", "knn"]
repeats = 2
jobs = 1
report = false
cache_dir = "{cache}"
"""


def _execute(notebook: Path, parameters: str, cwd: Path) -> nbformat.NotebookNode:
    """Run every cell of ``notebook`` in a fresh kernel, ``parameters`` after the tagged cell."""
    nb = nbformat.read(notebook, as_version=4)
    tagged = [i for i, c in enumerate(nb.cells) if "parameters" in c.metadata.get("tags", [])]
    assert len(tagged) == 1, "the notebook has one cell tagged 'parameters'"
    injected = nbformat.v4.new_code_cell(parameters, metadata={"tags": ["injected-parameters"]})
    nb.cells.insert(tagged[0] + 1, injected)
    client = nbclient.NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(cwd)}}
    )
    client.execute()
    return nb


def _text(cell: nbformat.NotebookNode) -> str:
    """What a code cell showed: its printed text, its value as plain text and as Markdown."""
    parts = []
    for output in cell.outputs:
        if output.output_type == "stream":
            parts.append(output.text)
        elif output.output_type in ("execute_result", "display_data"):
            parts += [output.data.get(kind, "") for kind in ("text/plain", "text/markdown")]
    return "\n".join(parts)


def test_the_notebook_and_the_command_write_the_same_folder(sdt_main, tmp_path, monkeypatch):
    # the kernel's connection files and IPython's profile go to the test's folder
    monkeypatch.setenv("JUPYTER_RUNTIME_DIR", str(tmp_path / "jupyter"))
    monkeypatch.setenv("IPYTHONDIR", str(tmp_path / "ipython"))
    config = tmp_path / "small.toml"
    config.write_text(CONFIG.format(cache=tmp_path / "cache"), encoding="utf-8")
    command, notebook = tmp_path / "command", tmp_path / "notebook"

    code, out, err = sdt_main("benchmark", str(config), "--out", str(command))
    assert code == 0, err
    # 1 machine x 3 scenarios x 2 sensors x 2 classifiers x 2 repeats
    assert "24 runs (24 computed, 0 resumed, 0 failed)" in out

    parameters = f"config_file = {str(config)!r}\noverrides = {{}}\nout = {str(notebook)!r}"
    ran = _execute(NOTEBOOK, parameters, tmp_path)

    assert_same_outputs(notebook, command, BENCH_TABLES, BENCH_TEXTS)
    assert sorted(p.name for p in notebook.iterdir()) == sorted(p.name for p in command.iterdir())
    shown = "\n".join(_text(c) for c in ran.cells if c.cell_type == "code")
    assert f"24 runs (24 computed, 0 resumed, 0 failed); results in {notebook}" in shown
    assert (command / "table4.md").read_text(encoding="utf-8") in shown  # Table 4, as written


def test_the_notebook_is_valid_and_committed_without_outputs():
    """Outputs kept in the file would be shown on the page and never checked."""
    nb = nbformat.read(NOTEBOOK, as_version=4)
    nbformat.validate(nb)
    assert all(not c.get("outputs") for c in nb.cells if c.cell_type == "code")
    namespace: dict[str, object] = {}
    exec(nb.cells[1].source, namespace)  # the parameters cell: assignments only
    assert namespace["overrides"] == {"quick": True, "report": False}  # as the text says
