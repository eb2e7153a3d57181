"""A hostile campaign tree, through ``sdt dataset manifest``, benchmarks like a clean one.

The synthetic pump's Motor-2 (ch1) is written as TDMS in a tree that reuses
run names under each condition folder, keeps one run folder elsewhere behind
a symbolic link, holds a FIFO and a broken link, and names its machine
``@pump`` (a formula in a spreadsheet). On main before round 4 (issue 39, item
10) the manifest held one recording per run name, the benchmark stopped with
"no usable recordings", and the machine reached results.csv as a live formula.
"""

from __future__ import annotations

import csv
import os

import pandas as pd
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework.csv_cells import unescape_frame

MACHINE = "@pump"


def _write_tree(root) -> int:
    from nptdms import ChannelObject, TdmsWriter

    count, numbers = 0, {}
    for rec, data in open_synthetic(machines="Motor-2", channels="ch1", duration=1.5,
                                    acquisitions=2).iter_loaded():  # fmt: skip
        severity = "-" if rec.severity is None else str(rec.severity)
        numbers[(rec.condition, severity)] = numbers.get((rec.condition, severity), 0) + 1
        run = f"run{numbers[(rec.condition, severity)]}"  # run1 under every condition
        folder = root / "tree" / MACHINE / rec.condition / severity / run
        if (rec.condition, severity, run) == ("impeller", "2", "run1"):
            folder = root / "archive" / "impeller-2-run1"  # on another disk, linked
            (root / "tree" / MACHINE / "impeller" / "2").mkdir(parents=True)
            os.symlink(folder, root / "tree" / MACHINE / "impeller" / "2" / "run1")
        folder.mkdir(parents=True)
        props = {"wf_increment": 1 / rec.sampling_rate_hz, "unit_string": "g"}
        with TdmsWriter(folder / f"{rec.channel}.tdms") as writer:
            writer.write_segment(
                [ChannelObject("acc", f"a{i}", row, properties=props) for i, row in
                 enumerate(data)]
            )  # fmt: skip
        count += 1
    os.mkfifo(root / "tree" / MACHINE / "healthy" / "-" / "run1" / "ch2.tdms")
    os.symlink("missing.tdms", root / "tree" / MACHINE / "healthy" / "-" / "run2" / "ch2.tdms")
    return count


def test_a_hostile_tree_manifest_benchmarks(tmp_path, monkeypatch, sdt_main):
    monkeypatch.setenv("SDT_CACHE_DIR", str(tmp_path / "cache"))
    files = _write_tree(tmp_path)
    manifest = tmp_path / "manifest.csv"
    code, out, err = sdt_main("dataset", "manifest", str(tmp_path / "tree"), "--pattern",
                              "{machine}/{condition}/{severity}/{run}/{channel}.tdms",
                              "--out", str(manifest))  # fmt: skip
    assert code == 0, err
    assert f"{2 * files} rows from {files} files ({files} recordings); 2 not used" in out
    with open(manifest, encoding="utf-8", newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert {r["machine"] for r in rows} == {"'" + MACHINE}  # inert in a spreadsheet
    assert len({r["recording_id"] for r in rows}) == files  # one id per physical run
    code, out, err = sdt_main("benchmark", "--quick", "--classifiers", "lr", "--data",
                              str(manifest), "--out", str(tmp_path / "results"),
                              "--no-report")  # fmt: skip
    assert code == 0, err
    assert f"manifest: {files} recordings" in out
    results = pd.read_csv(tmp_path / "results" / "results.csv")
    assert set(results["machine"]) == {"'" + MACHINE}  # as a spreadsheet must see it
    assert set(unescape_frame(results)["machine"]) == {MACHINE}  # and as sdt reads it
    assert (results["status"] == "ok").all()
    assert results["macro_f1"].notna().all()
