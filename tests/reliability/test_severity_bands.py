"""V_RMS bands: clipped to the chain with a warning, and 2-1000 Hz tables (issue 40, item 3).

On main a LIS3DH in high-resolution mode (ODR 1344 Hz, bandwidth ODR/9 = 149 Hz)
had its V_RMS graded and labelled 10-1000 Hz with no warning; a 2-1000 Hz table
(ISO 10816-3:2009 Annex A, machines below 600 r/min) was refused by the table
validator. Now the band each sensor covers is named and a clipped one warned
about, naming both bands; a 2-1000 Hz table is a valid table, and grading the
windows' 10-1000 Hz V_RMS by it is refused with the reason, before any run.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from sdt_framework.severity import band_problem, load_zone_file

from ..severity.test_severity_tables import GOOD

LIS3DH_HR = "lis3dh[mode=hr]"
SLOW = GOOD.replace("boundaries =", "band_hz = [2.0, 1000.0]\nboundaries =")


@pytest.fixture(scope="module")
def lis3dh_folder(tmp_path_factory) -> Path:
    """A small benchmark of the reference and a LIS3DH in high-resolution mode."""
    from sdt_framework.bench.config import BenchmarkConfig
    from sdt_framework.bench.output import write_outputs
    from sdt_framework.bench.runner import plan_benchmark, run_benchmark
    from sdt_framework.registry import build_registry

    root = tmp_path_factory.mktemp("lis3dh")
    config = BenchmarkConfig(
        dataset_options={"duration": 1.5},
        machines=["Motor-2"],
        channels=["ch1", "ch4"],
        sensors=["wilcoxon-786b10", LIS3DH_HR],
        classifiers=["lr"],
        repeats=1,
        jobs=1,
        report=False,
        cache_dir=str(root / "cache"),
    )
    out = root / "results"
    write_outputs(run_benchmark(plan_benchmark(config, build_registry()), out), out)
    return out


#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


@pytest.mark.catalog
def test_a_chain_that_stops_at_149_hz_is_named_and_warned_about(sdt, lis3dh_folder) -> None:
    done = sdt("compare", str(lis3dh_folder), env={"COLUMNS": "250"})
    assert done.returncode == 0, done.stderr
    name = "lis3dh[mode=hr,odr=1344,range=2g]"
    assert (
        f"warning: {name}: V_RMS covers 10-149.3 Hz, not the zone tables' 10-1000 Hz: its "
        f"chain passes up to 149.3 Hz (its lowest cut-off or Nyquist frequency), so its "
        f"zones grade what lies below 149.3 Hz only\n"
    ) in done.stderr
    assert "10-149.3 Hz (clipped)" in done.stdout  # the V_RMS band column
    assert "warning: wilcoxon-786b10" not in done.stderr  # 10 kHz: its band is whole


def test_a_2_to_1000_hz_table_is_a_valid_table(tmp_path) -> None:
    path = tmp_path / "slow.toml"
    path.write_text(SLOW, encoding="utf-8")
    (table,) = load_zone_file(path)
    assert table.band_hz == (2.0, 1000.0)
    assert "needs windows of at least 2 s" in band_problem(table, 0.64)


def test_grading_windows_by_a_2_to_1000_hz_table_is_refused_with_the_reason(sdt, tmp_path):
    path = tmp_path / "slow.toml"
    path.write_text(SLOW, encoding="utf-8")
    done = sdt("compare", str(tmp_path / "no-results"), "--zones", f"Motor-2={path}")
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr == (
        f"error: --zones 'Motor-2={path}': zone table 'plant-p101' grades V_RMS over "
        "2-1000 Hz (machines below 600 r/min); the features' V_RMS is 10-1000 Hz, and a 2 Hz "
        "edge needs windows of at least 2 s: grade the windows with a 10-1000 Hz table, or "
        "read the 2-1000 Hz overall off a whole recording "
        "(severity.velocity_spectrum(x, fs, band=(2, 1000)).overall)\n"
    )


def test_a_benchmark_config_with_a_2_to_1000_hz_table_stops_before_any_run(sdt, tmp_path):
    (tmp_path / "slow.toml").write_text(SLOW, encoding="utf-8")
    config = tmp_path / "zones.toml"
    config.write_text(
        f'[benchmark]\nmachines = ["Motor-4"]\nzones = {{ "Motor-4" = "{tmp_path}/slow.toml" }}\n',
        encoding="utf-8",
    )
    done = sdt("benchmark", str(config), "--quick", "--out", str(tmp_path / "out"))
    assert done.returncode == 2
    assert "[benchmark] zones: Motor-4: zone table 'plant-p101' grades V_RMS over 2-1000 Hz" in (
        done.stderr
    )
    assert "over 0.64 s windows" in done.stderr
    assert not (tmp_path / "out" / "results.parquet").exists()


def test_a_band_iso_does_not_grade_in_is_one_line(sdt, tmp_path) -> None:
    path = tmp_path / "odd.toml"
    path.write_text(GOOD.replace("boundaries =", "band_hz = [5, 500]\nboundaries ="))
    done = sdt("compare", str(tmp_path / "no-results"), "--zones", str(path))
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr == (
        f"error: {path}: field 'table.0.band_hz': band [5.0, 500.0] Hz is not a band ISO "
        "grades V_RMS in; write band_hz = [10.0, 1000.0], or [2.0, 1000.0] for a machine "
        "below 600 r/min (ISO 10816-3:2009 Annex A)\n"
    )


def test_a_sensor_the_registry_does_not_know_is_said_not_checked(registry) -> None:
    from sdt_framework.severity import sensor_bandwidths, vrms_bands

    widths = sensor_bandwidths(["adxl345", "from-a-sensor-file"], registry.sensor)
    assert widths == {"adxl345": 1599.0, "from-a-sensor-file": None}
    bands, warnings = vrms_bands(widths)
    assert bands.set_index("sensor")["label"].to_dict() == {
        "adxl345": "10-1000 Hz",
        "from-a-sensor-file": "10-1000 Hz (not checked)",
    }
    assert warnings == [
        "from-a-sensor-file: its chain is not known here, so whether its V_RMS covers "
        "10-1000 Hz is not checked"
    ]
