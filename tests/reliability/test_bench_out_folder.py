"""`--out`: nothing a user owns and no other benchmark's results are ever overwritten.

An sdt results folder is recognised by its marker ``.sdt-results.json``
(written first) or, for folders from before the marker, by the header of its
``config.toml``; it is resumed only by the configuration that wrote it.
"""

from __future__ import annotations

import json

import pytest

from sdt_framework import SDTError
from sdt_framework.bench.output import write_outputs
from sdt_framework.bench.runner import plan_benchmark, run_benchmark

#: the one command here is refused before any work: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


def finish(config, registry, out):
    result = run_benchmark(plan_benchmark(config, registry), out)
    write_outputs(result, out)
    return result


def snapshot(folder):
    return {p.relative_to(folder): p.read_bytes() for p in folder.rglob("*") if p.is_file()}


def test_a_folder_sdt_did_not_write_is_refused_and_left_alone(small_config, registry, tmp_path):
    out = tmp_path / "thesis"
    out.mkdir()
    (out / "chapter1.docx").write_bytes(b"months of work")
    before = snapshot(out)
    with pytest.raises(SDTError, match=r"is not an sdt results folder and not empty \(it holds "):
        run_benchmark(plan_benchmark(small_config(), registry), out)
    assert snapshot(out) == before


def test_a_results_folder_holding_a_foreign_file_is_refused(small_config, registry, tmp_path):
    out = tmp_path / "out"
    finish(small_config(), registry, out)
    (out / "notes.txt").write_text("mine")
    before = snapshot(out)
    with pytest.raises(SDTError, match=r"holds files sdt did not write \(notes.txt\)"):
        run_benchmark(plan_benchmark(small_config(), registry), out)
    assert snapshot(out) == before


def test_another_configuration_is_refused_naming_what_differs(small_config, registry, tmp_path):
    out = tmp_path / "out"
    finish(small_config(), registry, out)
    before = snapshot(out)
    with pytest.raises(SDTError) as caught:
        run_benchmark(plan_benchmark(small_config(repeats=3, seed=7), registry), out)
    message = str(caught.value)
    assert "holds the results of another configuration" in message
    assert "repeats: 2 -> 3" in message and "seed: 0 -> 7" in message
    assert "\n" not in message
    assert snapshot(out) == before  # results.csv and config.toml of the first one intact


def test_the_same_configuration_resumes_whatever_the_jobs(small_config, registry, tmp_path):
    out = tmp_path / "out"
    finish(small_config(), registry, out)
    again = finish(small_config(jobs=2, cache_dir=str(tmp_path / "other-cache")), registry, out)
    assert (again.runs_resumed, again.runs_computed) == (12, 0)


def test_an_empty_or_new_folder_is_claimed_with_the_marker_first(small_config, registry, tmp_path):
    from sdt_framework.bench.folder import MARKER

    empty = tmp_path / "empty"
    empty.mkdir()
    for out in (empty, tmp_path / "new" / "deeper"):
        finish(small_config(), registry, out)
        marker = json.loads((out / MARKER).read_text())
        assert marker["format"] == "sdt-framework benchmark results"
        assert marker["configuration"]["repeats"] == 2 and "jobs" not in marker["configuration"]


def test_a_folder_from_before_the_marker_is_recognised_by_its_config(
    small_config, registry, tmp_path
):
    from sdt_framework.bench.folder import MARKER

    out = tmp_path / "out"
    finish(small_config(), registry, out)
    (out / MARKER).unlink()
    assert finish(small_config(), registry, out).runs_resumed == 12
    (out / MARKER).unlink()
    with pytest.raises(SDTError, match="repeats: 2 -> 1"):
        run_benchmark(plan_benchmark(small_config(repeats=1), registry), out)


def test_out_that_is_a_file_is_one_line_and_exit_2(sdt, tmp_path):
    target = tmp_path / "results.csv"
    target.write_text("a,b\n1,2\n")
    result = sdt("benchmark", "--quick", "--machines", "Motor-2", "--out", str(target))
    assert result.returncode == 2
    assert result.stderr.strip() == (
        f"error: --out {target} is a file; name a folder (new or empty, or a results folder "
        f"to resume)"
    )
    assert target.read_text() == "a,b\n1,2\n"
