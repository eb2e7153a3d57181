"""Cross-chain runs: trained on one chain, tested on another.

Two checks against independent reasoning:

- ``S -> S`` is the ordinary run of S: same split, seeds and noise draws, so
  its numbers equal the ordinary rows bit for bit (and the ordinary rows equal
  those of a benchmark without transfer pairs).
- ``A -> B`` where B is A with every amplitude doubled (a +100 % ``scale``
  stage on the identity chain): four classes of pure 50 Hz sines at 0.1, 0.2,
  0.4 and 0.8 g differ only in amplitude, so B's windows of class k are A's
  windows of class k+1 (the sine's shape features are the same for all), and
  a classifier trained on A calls class k "k+1" and the top class itself. Per
  class F1: 0, 0, 0 and 2/3 (class 3 is predicted for classes 2 and 3):
  Macro F1 = 1/6, against 1 for ``A -> A`` and ``B -> B``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from sdt_framework.bench.results import tidy
from sdt_framework.bench.runner import plan_benchmark, run_benchmark

FS = 4000  # Hz; 0.64 s windows hold 32 whole 50 Hz periods, starting at phase 0
AMPLITUDES = {"c0": 0.1, "c1": 0.2, "c2": 0.4, "c3": 0.8}
STAGES = 'stages = [{name = "scale", params = {error_pct = 100.0}}]\n'


def _amplitude_data(folder: Path, fs: int = FS) -> Path:
    t = np.arange(int(3.0 * fs)) / fs
    lines = ["path,sampling_rate_hz,machine,condition,severity,recording_id,channel"]
    for condition, amplitude in AMPLITUDES.items():
        for severity in (1, 2, 3):
            name = f"{condition}_{severity}"
            np.save(folder / f"{name}.npy", amplitude * np.sin(2 * np.pi * 50 * t))
            lines.append(f"{name}.npy,{fs},m,{condition},{severity},{name},ch1")
    for name, stages in (("plain", ""), ("doubled", STAGES)):
        (folder / f"{name}.toml").write_text(
            f'[sensor]\nname = "{name}"\ndescription = "identity chain"\nsource = "test"\n'
            'sampling_rate_hz = "native"\nfull_scale_g = 100.0\nadc_bits = 24\n'
            "noise_density_ug_rthz = 0\ninject_noise = false\nrequantise = false\n"
            f"mech_cutoff_hz = 1e6\nanalog_cutoff_hz = 1e6\n{stages}"
        )  # cut-offs far above any Nyquist: no filter acts
    manifest = folder / "m.csv"
    manifest.write_text("\n".join(lines) + "\n")
    return manifest


def test_training_on_a_chain_that_halves_amplitudes_shifts_every_class_up(sdt_main, tmp_path):
    manifest = _amplitude_data(tmp_path)
    out = tmp_path / "out"
    code, _, err = sdt_main(
        "--sensor-file", str(tmp_path / "plain.toml"), "--sensor-file",
        str(tmp_path / "doubled.toml"), "benchmark", "--data", str(manifest),
        "--sensors", "plain,doubled", "--classifiers", "lr,knn",
        "--scenarios", "interpolation", "--repeats", "1", "--jobs", "1", "--no-report",
        "--transfer", "plain -> doubled", "--out", str(out),
        "--cache-dir", str(tmp_path / "cache"),
    )  # fmt: skip
    assert code == 0, err
    results = pd.read_parquet(out / "results.parquet").set_index(["sensor", "classifier"])
    for clf in ("lr", "knn"):
        assert results.loc[("plain", clf), "macro_f1"] == 1.0
        assert results.loc[("doubled", clf), "macro_f1"] == 1.0
        assert results.loc[("plain -> doubled", clf), "macro_f1"] == pytest.approx(1 / 6)
    row = results.loc[("plain -> doubled", "lr")]
    assert (row["train_sensor"], row["test_sensor"]) == ("plain", "doubled")
    per_class = pd.read_parquet(out / "per_class.parquet")
    moved = per_class[per_class["sensor"] == "plain -> doubled"]
    assert moved.groupby("class")["f1"].mean().round(6).to_dict() == {
        "c0": 0.0, "c1": 0.0, "c2": 0.0, "c3": round(2 / 3, 6)
    }  # fmt: skip


def test_s_to_s_is_the_ordinary_run_bit_for_bit(small_config, registry, tmp_path):
    plain = run_benchmark(plan_benchmark(small_config(), registry), tmp_path / "plain")
    pairs = ["adxl345 -> adxl345", "wilcoxon-786b10 -> adxl345", "wilcoxon-786b10+adxl345 -> *"]
    crossed = run_benchmark(
        plan_benchmark(small_config(transfer=pairs), registry), tmp_path / "crossed"
    )
    results = tidy(crossed.runs)[0]
    keys = ["machine", "scenario", "classifier", "repeat"]
    ordinary = results[results["sensor"] == "adxl345"].set_index(keys)
    same = results[results["sensor"] == "adxl345 -> adxl345"].set_index(keys)
    assert len(ordinary) == len(same) > 0
    assert same["macro_f1"].equals(ordinary["macro_f1"])  # bit for bit
    assert (same["train_sensor"] == "adxl345").all()
    before = tidy(plain.runs)[0]
    assert before["macro_f1"].tolist() == results[~results["sensor"].str.contains("->")][
        "macro_f1"
    ].tolist()  # fmt: skip
    # a mix trains on both chains' training windows: twice the ordinary training set
    mix = results[results["sensor"] == "wilcoxon-786b10+adxl345 -> adxl345"]
    assert (mix["n_train"].to_numpy() == 2 * ordinary["n_train"].to_numpy()).all()
    assert set(results["sensor"]) == {
        "wilcoxon-786b10", "adxl345", "adxl345 -> adxl345", "wilcoxon-786b10 -> adxl345",
        "wilcoxon-786b10+adxl345 -> adxl345",
    }  # fmt: skip
    # nothing featurised twice: one block per (recording, sensor, repetition) either way
    assert crossed.features_computed + crossed.features_cached == (
        plain.features_computed + plain.features_cached
    )


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--transfer", "wilcoxon-786b10 -> nosuch"], "transfer 'wilcoxon-786b10 -> nosuch'"),
        (["--transfer", "adxl345"], "is not 'TRAIN -> TEST'"),
        (["--transfer", "reference -> adxl345", "--data", "{slow}", "--sensors",
          "native-reference"], "transfer 'native-reference -> adxl345': adxl345 cannot"),
        (["--sample", "node"], "sample = 'node' needs [benchmark] axes"),
        (["{axes}", "--sample", "node", "--channels", "ch1,ch2"], "is not one node"),
        (["{nodes}", "--channels", "ch1,ch2,ch4"], "nodes names the nodes of sample = 'node'"),
        (["{nodes}", "--sample", "node", "--channels", "ch1,ch2"],
         "has no channel 'ch4' of node 'de'"),
    ],
)  # fmt: skip
def test_bad_pairs_and_nodes_are_one_line_before_any_work(sdt_main, tmp_path, args, words):
    manifest = _amplitude_data(tmp_path)
    (tmp_path / "slow").mkdir()
    slow = _amplitude_data(tmp_path / "slow", fs=1000)  # slower than an ADXL345's 3200 Hz
    axes, nodes = tmp_path / "axes.toml", tmp_path / "nodes.toml"
    axes.write_text("[benchmark]\naxes = {ch1 = 'x', ch2 = 'y'}\n")
    nodes.write_text(
        "[benchmark]\naxes = {ch1 = 'x', ch2 = 'y', ch4 = 'z'}\n"
        "nodes = {de = ['ch1', 'ch2', 'ch4']}\n"
    )
    out = tmp_path / "out"
    code, _, err = sdt_main(
        "benchmark", "--quick", "--classifiers", "lr", "--out", str(out),
        *[a.format(manifest=manifest, slow=slow, axes=axes, nodes=nodes) for a in args],
    )  # fmt: skip
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and words in lines[0], err
    assert not out.exists()  # before any work


def test_transfer_and_nodes_resume_and_draw_units(small_config, registry, tmp_path):
    """With --units the pair trains on unit k of its chain and tests on unit k of the other;
    a second run of the same configuration resumes every run and featurises nothing."""
    config = small_config(
        units=2, transfer=["adxl345 -> adxl345", "wilcoxon-786b10 -> adxl345"],
        channels=["ch1", "ch2", "ch4"], axes={"ch1": "x", "ch2": "y", "ch4": "z"},
        sample="node", classifiers=["lr"], repeats=1,
    )  # fmt: skip
    first = run_benchmark(plan_benchmark(config, registry), tmp_path / "out")
    results = tidy(first.runs)[0]
    keys = ["machine", "scenario", "classifier", "repeat", "unit"]
    ordinary = results[results["sensor"] == "adxl345"].set_index(keys)["macro_f1"]
    same = results[results["sensor"] == "adxl345 -> adxl345"].set_index(keys)["macro_f1"]
    assert sorted(set(results["unit"])) == [0, 1]
    assert same.sort_index().equals(ordinary.sort_index())
    again = run_benchmark(plan_benchmark(config, registry), tmp_path / "out")
    assert again.runs_computed == 0 and again.runs_resumed == len(first.runs)
    assert again.features_computed == 0
    assert tidy(again.runs)[0]["macro_f1"].equals(results["macro_f1"])
