"""``sdt benchmark --scenarios speed-transfer`` end to end on the synthetic pump at three speeds.

A small run (Motor-2, one channel, 1.5 s acquisitions, LR, two repetitions,
the three default sensors): allocation.csv holds the speed-transfer arms, every
test run at the test speed and every training run at the training speeds (read
from the run's speed folder, ``<speed>/<run>``), both arms of a fold on the same
test runs; ``sdt compare --json`` gives the loss under the speed shift, checked
against results.csv paired by hand. Bad input: one line, exit 2.
"""

from __future__ import annotations

import json

import pandas as pd
import pytest

TOML = """[benchmark]
speeds = [50, 75, 100]
scenarios = ["speed-transfer"]
classifiers = ["lr"]
machines = ["Motor-2"]
channels = ["ch1"]
repeats = 2
jobs = 1
report = false
{extra}
[benchmark.dataset_options]
duration = 1.5
"""


def _config(tmp_path, extra="", name="config.toml"):
    path = tmp_path / name
    path.write_text(TOML.format(extra=extra))
    return path


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    """The results folder of the small run (one benchmark for the module's tests)."""
    import sys

    from sdt_framework.cli.main import main

    tmp = tmp_path_factory.mktemp("speed")
    out = tmp / "out"
    argv = sys.argv
    sys.argv = ["sdt", "benchmark", str(_config(tmp)), "--out", str(out),
                "--cache-dir", str(tmp / "cache")]  # fmt: skip
    try:
        main()
    except SystemExit as exc:
        assert not exc.code, exc.code
    finally:
        sys.argv = argv
    return out


def test_the_allocation_lists_each_fold_with_its_speeds(folder):
    allocation = pd.read_csv(folder / "allocation.csv")
    folds = {"50": {"75", "100"}, "75": {"50", "100"}, "100": {"50", "75"}}
    names = {f"speed {'+'.join(sorted(t, key=int))} -> {s}" for s, t in folds.items()}
    assert set(allocation["scenario"]) == names | {f"speed {s} -> {s}" for s in folds}
    speed = allocation["run"].str.split("/").str[0]
    for test, train in folds.items():
        shift = allocation["scenario"] == f"speed {'+'.join(sorted(train, key=int))} -> {test}"
        within = allocation["scenario"] == f"speed {test} -> {test}"
        testing, training = allocation["side"] == "test", allocation["side"] == "train"
        assert set(speed[shift & testing]) == set(speed[within & testing]) == {test}
        assert set(speed[shift & training]) == train
        assert set(speed[within & training]) == {test}
        assert set(allocation["run"][shift & testing]) == set(allocation["run"][within & testing])
        # no run trains and tests in one arm
        assert not set(allocation["run"][shift & testing]) & set(
            allocation["run"][shift & training]
        )


def test_compare_gives_the_loss_under_the_speed_shift(folder, sdt_main):
    code, out, err = sdt_main("compare", str(folder), "--json")
    assert code == 0, err
    loss = pd.DataFrame(json.loads(out)["speed_loss"]["per_sensor"])
    results = pd.read_csv(folder / "results.csv")
    assert set(loss["sensor"]) == {"wilcoxon-786b10", "adxl345", "adxl357"}
    assert len(loss) == 3 * 3  # three folds x three sensors
    # one channel, one test run per class: no test set to resample, and the reason given
    assert set(loss["rec_note"]) == {"1 test recording in some class: nothing to resample"}
    for row in loss.itertuples():
        f1 = results[(results["sensor"] == row.sensor)].set_index(["scenario", "repeat"])
        by_hand = (f1.loc[row.within, "macro_f1"] - f1.loc[row.shift, "macro_f1"]).mean()
        assert row.loss == pytest.approx(by_hand)
    per_class = pd.DataFrame(json.loads(out)["speed_loss"]["per_class"])
    assert set(per_class["class"]) == set(pd.read_parquet(folder / "per_class.parquet")["class"])

    code, text, err = sdt_main("compare", str(folder))
    assert code == 0, err
    assert "Macro F1 under a speed shift" in text and "excess +" in text
    assert "loss of F1 per class" in text


@pytest.mark.parametrize(
    ("extra", "line"),
    [
        (
            "speed_transfer = {train = [100], test = [100]}",
            "field 'speed_transfer': 100 is both a training and a test speed",
        ),
        (
            "speed_transfer = {train = [100], test = [60]}",
            "error: speed_transfer test: no run at 60; the data has Motor-2 at 50, 75, 100",
        ),
    ],
)
def test_bad_speed_transfer_settings_are_one_line_and_exit_2(tmp_path, sdt_main, extra, line):
    out = tmp_path / "out"
    code, _, err = sdt_main("benchmark", str(_config(tmp_path, extra)), "--out", str(out))
    assert code == 2
    assert len(err.strip().splitlines()) == 1 and line in err, err


def test_one_speed_under_speed_transfer_is_one_line_and_exit_2(tmp_path, sdt_main):
    path = tmp_path / "one.toml"
    path.write_text(TOML.format(extra="").replace("[50, 75, 100]", "[100]"))
    code, _, err = sdt_main("benchmark", str(path), "--out", str(tmp_path / "out"))
    assert code == 2
    assert err.strip() == (
        "error: speed transfer needs runs at two speeds or more on one machine; the data has "
        "Motor-2 at 100: read more speeds (speeds = [50, 75, 100] in [benchmark], for the "
        "synthetic pump or an NLN-EMP archive)"
    )


def test_the_report_shows_the_loss_per_sensor_and_per_class(folder):
    from sdt_framework.report.document import Heading, Table
    from sdt_framework.report.load import load_results
    from sdt_framework.report.speed import speed_blocks

    blocks = speed_blocks(load_results(folder))
    headings = [b.text for b in blocks if isinstance(b, Heading)]
    assert headings == [
        "Speed transfer: the loss under a speed shift",
        "Motor-2: per sensor",
        "Motor-2: per class",
    ]
    per_sensor, per_class = [b for b in blocks if isinstance(b, Table)]
    results = pd.read_csv(folder / "results.csv").set_index(["scenario", "sensor", "repeat"])
    row = next(r for r in per_sensor.rows if r[0] == "adxl357")  # the first fold: 50
    assert per_sensor.rows[0][0] == "**speed 75+100 -> 50**"
    by_hand = (
        results.loc[("speed 50 -> 50", "adxl357"), "macro_f1"]
        - results.loc[("speed 75+100 -> 50", "adxl357"), "macro_f1"]
    ).mean()
    assert row[4].startswith(f"{by_hand:+.3f}")
    classes = set(pd.read_parquet(folder / "per_class.parquet")["class"])
    assert set(per_class.header[1:]) == classes


def test_fig6_draws_a_chart_per_speed_arm(folder):
    """Before, a folder of speed arms alone left Fig. 6 undrawn ('Number of columns must be a
    positive integer, not 0'): the figure knew the paper's three scenarios only."""
    from sdt_framework.report.figures_scores import plot_radar

    per_class = pd.read_parquet(folder / "per_class.parquet")
    sensors = ["wilcoxon-786b10", "adxl345", "adxl357"]
    fig = plot_radar(per_class, sensors, {})
    titles = [ax.get_title() for ax in fig.axes]
    assert len(titles) == 6
    assert "Motor-2 — Speed transfer: trained at 75+100, tested at 50" in titles
    assert "Motor-2 — Within speed: trained and tested at 50" in titles


def test_speeds_all_on_the_command_line_points_to_the_dataset_option(tmp_path, sdt_main):
    code, _, err = sdt_main("benchmark", "--speeds", "all", "--out", str(tmp_path / "out"))
    assert code == 2
    assert err.strip() == (
        "error: command line: field 'speeds': give the speeds to use, e.g. [50, 75, 100] "
        "(--speeds 50,75,100); every speed a dataset holds: dataset_options speeds = 'all' "
        "(got 'all')"
    )


def test_split_all_has_no_loss_and_compare_says_why(tmp_path, sdt_main):
    extra = 'speed_transfer = {train = [50, 100], test = [75], split = "all"}'
    out = tmp_path / "out"
    code, _, err = sdt_main("benchmark", str(_config(tmp_path, extra)), "--out", str(out),
                            "--cache-dir", str(tmp_path / "cache"))  # fmt: skip
    assert code == 0, err
    assert set(pd.read_csv(out / "allocation.csv")["scenario"]) == {"speed 50+100 -> 75"}
    code, text, err = sdt_main("compare", str(out))
    assert code == 0, err
    assert (
        "speed transfer: speed 50+100 -> 75: no within-speed arm to take the loss against "
        "(split = 'all' has none; or it was skipped: skipped.csv); Table 4 shows their Macro F1"
    ) in " ".join(text.split())
    code, text, _ = sdt_main("compare", str(out), "--json")
    assert json.loads(text)["speed_loss"]["unpaired"] == ["speed 50+100 -> 75"]
