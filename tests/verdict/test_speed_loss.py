"""The loss under a speed shift, against figures worked out by hand (issue 43).

Two sensors, one classifier, two repetitions of one fold tested at 75: the
within-speed arm ``speed 75 -> 75`` and the shift arm ``speed 100 -> 75``. The
loss of a repetition is within minus shifted; its 95 % interval over two
repetitions is mean ± t(0.975, 1) · sd / √2 with t(0.975, 1) = 12.7062 (tables).
"""

from __future__ import annotations

import math

import pandas as pd
import pytest

from sdt_framework.verdict.speed_loss import speed_arms, speed_loss, speed_loss_by_class

T_975_1 = 12.706204736174698  # Student t, 0.975 quantile, 1 degree of freedom

#: (scenario, sensor, repeat) -> Macro F1
F1 = {
    ("speed 75 -> 75", "ref", 0): 0.90, ("speed 75 -> 75", "ref", 1): 0.80,
    ("speed 100 -> 75", "ref", 0): 0.70, ("speed 100 -> 75", "ref", 1): 0.70,
    ("speed 75 -> 75", "cheap", 0): 0.85, ("speed 75 -> 75", "cheap", 1): 0.75,
    ("speed 100 -> 75", "cheap", 0): 0.45, ("speed 100 -> 75", "cheap", 1): 0.25,
    ("forward", "ref", 0): 0.99,  # not a speed arm: ignored
}  # fmt: skip


def _results(status=None):
    rows = [
        {"machine": "M", "scenario": s, "sensor": n, "feature_set": "paper8", "classifier": "lr",
         "unit": -1, "repeat": r, "macro_f1": v, "status": (status or {}).get((s, n, r), "ok")}
        for (s, n, r), v in F1.items()
    ]  # fmt: skip
    return pd.DataFrame(rows)


def test_the_loss_is_within_minus_shifted_paired_by_repetition():
    table = speed_loss(_results(), baseline="ref").set_index("sensor")
    assert list(table["shift"].unique()) == ["speed 100 -> 75"]
    ref, cheap = table.loc["ref"], table.loc["cheap"]
    # ref: losses 0.20, 0.10 -> mean 0.15, sd 0.0707
    assert ref["loss"] == pytest.approx(0.15)
    half = T_975_1 * math.sqrt(0.005) / math.sqrt(2)
    assert (ref["loss_low"], ref["loss_high"]) == pytest.approx((0.15 - half, 0.15 + half))
    assert ref["within_f1"] == pytest.approx(0.85) and ref["shift_f1"] == pytest.approx(0.70)
    # cheap: losses 0.40, 0.50 -> mean 0.45; excess over ref per repetition 0.20, 0.40
    assert cheap["loss"] == pytest.approx(0.45)
    assert cheap["excess"] == pytest.approx(0.30)
    half = T_975_1 * math.sqrt(0.02) / math.sqrt(2)
    assert (cheap["excess_low"], cheap["excess_high"]) == pytest.approx((0.3 - half, 0.3 + half))
    assert math.isnan(ref["excess"])  # the baseline has no excess over itself
    assert int(cheap["n"]) == 2


def test_a_failed_run_leaves_its_repetition_out_of_the_pair():
    results = _results(status={("speed 100 -> 75", "cheap", 1): "failed"})
    cheap = speed_loss(results, baseline="ref").set_index("sensor").loc["cheap"]
    assert cheap["loss"] == pytest.approx(0.40) and int(cheap["n"]) == 1
    assert math.isnan(cheap["loss_low"])  # one repetition: no interval


def test_a_shift_arm_without_its_within_arm_is_not_paired():
    results = _results()
    assert speed_arms(results["scenario"]) == [("speed 100 -> 75", "speed 75 -> 75")]
    alone = results[results["scenario"] != "speed 75 -> 75"]
    assert speed_arms(alone["scenario"]) == []
    assert speed_loss(alone).empty


def test_the_loss_per_class_is_the_mean_over_paired_runs():
    rows = []
    for (scenario, sensor, repeat), _ in F1.items():
        for name, f1 in (("healthy", 0.9), ("fault", 0.6)):
            shifted = scenario == "speed 100 -> 75"
            value = f1 - (0.1 * (repeat + 1) if shifted and name == "fault" else 0)
            rows.append({"machine": "M", "scenario": scenario, "sensor": sensor,
                         "feature_set": "paper8", "classifier": "lr", "unit": -1,
                         "repeat": repeat, "class": name, "f1": value})  # fmt: skip
    table = speed_loss_by_class(pd.DataFrame(rows)).set_index(["sensor", "class"])
    assert table.loc[("ref", "fault"), "loss"] == pytest.approx(0.15)  # 0.1 and 0.2
    assert table.loc[("ref", "healthy"), "loss"] == pytest.approx(0.0)
    assert int(table.loc[("cheap", "fault"), "n"]) == 2


def test_the_recording_interval_spans_the_test_sets_a_resample_can_draw():
    """Two classes of two test recordings (10 windows each). Within speed every window is
    right; shifted, recording a1 is all called b. A stratified resample draws class a as
    (a1, a1), (a1, a2) or (a2, a2), each at least 1/4 likely, so the 2.5 and 97.5
    percentiles of 2000 draws are the smallest and largest loss of those three test sets,
    each worked out here with sklearn's f1_score on the windows' labels."""
    from sklearn.metrics import f1_score

    from sdt_framework.verdict.speed_recordings import recording_intervals

    truth = {"a1": "a", "a2": "a", "b1": "b", "b2": "b"}
    rows = []
    for scenario in ("speed 75 -> 75", "speed 100 -> 75"):
        for rec, true in truth.items():
            wrong = scenario == "speed 100 -> 75" and rec == "a1"
            rows.append({"machine": "M", "scenario": scenario, "sensor": "s",
                         "feature_set": "paper8", "classifier": "lr", "repeat": 0,
                         "recording_id": rec, "true": true, "predicted": "b" if wrong else true,
                         "count": 10})  # fmt: skip
    per_recording = pd.DataFrame(rows)

    def loss(drawn: list[str]) -> float:
        drawn = [*drawn, "b1", "b2"]
        y = [truth[r] for r in drawn for _ in range(10)]
        shifted = ["b" if r == "a1" else truth[r] for r in drawn for _ in range(10)]
        return 1.0 - f1_score(y, shifted, average="macro")

    outcomes = [loss(["a1", "a1"]), loss(["a1", "a2"]), loss(["a2", "a2"])]
    assert outcomes == pytest.approx([2 / 3, 1 - (2 / 3 + 0.8) / 2, 0.0])
    results = per_recording.drop_duplicates(["scenario"])[
        ["machine", "scenario", "sensor", "feature_set", "classifier", "repeat"]
    ].assign(macro_f1=[1.0, 1 - outcomes[1]], status="ok", unit=-1)
    table = recording_intervals(speed_loss(results), per_recording)
    row = table.iloc[0]
    assert row["loss"] == pytest.approx(outcomes[1])
    assert (row["rec_low"], row["rec_high"]) == pytest.approx((min(outcomes), max(outcomes)))
    assert row["rec_note"] == ""


def test_one_test_recording_in_a_class_gives_no_recording_interval_and_says_why():
    from sdt_framework.verdict.speed_recordings import recording_intervals

    rows = [
        {"machine": "M", "scenario": s, "sensor": "s", "feature_set": "paper8",
         "classifier": "lr", "repeat": 0, "recording_id": r, "true": r[0], "predicted": r[0],
         "count": 5}
        for s in ("speed 75 -> 75", "speed 100 -> 75") for r in ("a1", "b1", "b2")
    ]  # fmt: skip
    results = _results()
    table = recording_intervals(speed_loss(results[results["sensor"] == "ref"]), pd.DataFrame(rows))
    assert math.isnan(table.iloc[0]["rec_low"])
    assert table.iloc[0]["rec_note"] == "no per-recording counts stored for this cell"
    rows = [{**r, "sensor": "ref"} for r in rows]
    table = recording_intervals(speed_loss(results[results["sensor"] == "ref"]), pd.DataFrame(rows))
    assert table.iloc[0]["rec_note"] == "1 test recording in some class: nothing to resample"
