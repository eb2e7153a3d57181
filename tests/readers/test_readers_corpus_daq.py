"""What the corpus's LVM, UFF and TDMS files hold (tests/data/readers/corpus, its README), as
their reference libraries (lvm_read, pyuff, npTDMS) read them, and the excerpts sdt refuses.

``test_readers_corpus.py`` compares every readable signal's values with the library's; here
each file's channels, rates, units and lengths are checked against figures known from the
file (its header, its source's description), and each signal sdt lists but refuses is
refused for a reason the file itself shows.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sdt_framework.data.recording import DataFileError
from sdt_framework.signals.files import scan_file

from .daq_files import CATMAN, CORPUS, PSD


def _infos(registry, file: Path) -> dict:
    return {i.variable: i for i in scan_file(file, registry.signal_readers())[1]}


@pytest.mark.parametrize(
    ("name", "readable"),
    [
        ("arts-lab-dataset5-Test_001.lvm", {"Acceleration_0": (51_200, 51_200.0, "m/s^2"),
                                            "Acceleration_1": (51_200, 51_200.0, "m/s^2")}),
        ("lvm_read-no_decimal_separator.lvm", {a: (4, 4000.0, "g") for a in ("ax", "ay", "az")}),
        ("lvm_read-long_single_header_multi_ch.lvm", {"F": (16_384, 1 / 0.000977, "g"),
                                                      "m_1": (16_384, 1 / 0.000977, "m/s^2"),
                                                      "m_2": (16_384, 1 / 0.000977, "m/s^2")}),
    ],
)  # fmt: skip
def test_lvm_channels_rates_and_units(registry, name, readable):
    """The header cell of data column c is lvm_read's cell c - 1 where the file has X columns
    (One, Multi), cell c where it has none (No), as NI's LVM specification lays them out."""
    import lvm_read

    file = CORPUS / name
    infos = _infos(registry, file)
    lvm = lvm_read.read(str(file), read_from_pickle=False, dump_file=False)
    segment, offset = lvm[0], 0 if lvm["X_Columns"] == "No" else 1
    for variable, (n, rate, units) in readable.items():
        cell = segment["Channel names"].index(variable) - offset
        info = infos[variable]
        assert info.fault is None
        assert (info.n_samples, info.units) == (n, units) == (n, segment["Y_Unit_Label"][cell])
        assert info.rate_hz == pytest.approx(rate, rel=1e-12)
        assert info.rate_hz == 1 / segment["Delta_X"][cell]


def test_lvm_channels_shorter_than_the_file_are_their_samples_count(registry):
    """ARTS-Lab's Test_001.lvm logs four 1 Hz impedance channels of 5 values under two 51.2 kHz
    accelerometers (LabVIEW: "X values guaranteed valid only for Acceleration_0"): each is
    listed with its own 5 samples (lvm_read's column holds 5 values, then NaN) and refused
    for its 1 Hz rate, which the accelerometers beside it do not share."""
    import lvm_read

    file = CORPUS / "arts-lab-dataset5-Test_001.lvm"
    segment = lvm_read.read(str(file), read_from_pickle=False, dump_file=False)[0]
    infos = _infos(registry, file)
    for name in ("Untitled", "Untitled 1", "Untitled 2", "Untitled 3"):
        column = segment["data"][:, segment["Channel names"].index(name)]
        assert np.isfinite(column[:5]).all() and np.isnan(column[5:]).all()
        assert infos[name].n_samples == 5
        assert "Delta_X is 1 s, a rate of 1 Hz, outside 25 Hz" in infos[name].fault


@pytest.mark.parametrize(
    ("name", "rows", "samples"),
    [("multi_time_column.lvm", 3, "51,200"), ("with_empty_fields.lvm", 7, "100")],
)
def test_lvm_excerpts_whose_samples_exceed_their_rows_are_refused(registry, name, rows, samples):
    """lvm_read's test files cut a real recording to a few rows and keep its header: sdt refuses
    them as cut short, naming the header's Samples and the rows lvm_read finds."""
    import lvm_read

    file = CORPUS.parent / name
    segment = lvm_read.read(str(file), read_from_pickle=False, dump_file=False)[0]
    assert len(segment["data"]) == rows
    with pytest.raises(DataFileError, match=f"holds {rows} rows, its header's Samples says "
                       f"{samples}; the file was cut short"):  # fmt: skip
        scan_file(file, registry.signal_readers())


def test_catman_uff_time_history(registry):
    """HBM catman's export (pyuff's test file): its closing -1 is padded to 80 columns."""
    import pyuff

    dataset = pyuff.UFF(str(CATMAN)).read_sets(0)
    info = _infos(registry, CATMAN)["1"]
    assert (info.n_samples, info.units, info.fault) == (13, "m/s²", None)
    assert info.rate_hz == 1 / dataset["abscissa_inc"] == pytest.approx(20_000.0)


def test_a_uff_of_power_spectral_densities_is_refused_naming_them(registry):
    import pyuff

    uff = pyuff.UFF(str(PSD))
    assert list(uff.get_set_types()) == [58] and uff.read_sets(0)["func_type"] == 9
    with pytest.raises(DataFileError, match="dataset 58 #1 is a power spectral density"):
        scan_file(PSD, registry.signal_readers())


@pytest.mark.parametrize(
    ("name", "faulty"),
    [
        ("npTDMS-Digital_Input.tdms", {"Decimated Data_Level2": "a rate of 0.8 Hz, outside"}),
        ("npTDMS-big_endian.tdms", {}),
        ("npTDMS-raw_timestamps.tdms", {}),
    ],
)
def test_tdms_channels_are_nptdms_groups_and_channels(registry, name, faulty):
    """Every channel npTDMS finds is listed by its group and channel names, at 1 / wf_increment;
    Digital_Input.tdms (LabVIEW) names its groups with dates holding '/'."""
    from nptdms import TdmsFile

    file = CORPUS / name
    infos = _infos(registry, file)
    channels = [(g, c) for g in TdmsFile.read_metadata(file).groups() for c in g.channels()]
    assert len(infos) == len(channels)
    for group, channel in channels:
        info = infos[f"{group.name}/{channel.name}"]
        why = next((w for key, w in faulty.items() if key in group.name), None)
        assert (why or "") in (info.fault or "")
        assert info.rate_hz == 1 / channel.properties["wf_increment"]
