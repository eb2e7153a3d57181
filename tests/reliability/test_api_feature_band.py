"""A rate at which a feature band is empty is refused, not turned into features equal to 0.

paper8 (SPEC section 3) sums the spectrum of a window over 10 Hz <= f_k <= fs/2 (A_RMS,
A_Peak) and over 10 <= f_k <= 1000 Hz (V_RMS, D_RMS). At fs = 15 Hz the Nyquist frequency is
7.5 Hz: both bands are empty and, before this check, `sdt features extract --fs 15` wrote
four columns of zeros with exit 0. The expected outcome here is computed independently, by
listing the FFT bin frequencies k fs / N of an N = round(0.64 fs) sample window.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from pydantic import ValidationError

from sdt_framework import FeatureSetSpec, SDTError, build_registry
from sdt_framework.api import extract
from sdt_framework.cli.main import main
from sdt_framework.features import compose


@pytest.fixture(scope="module")
def paper8() -> FeatureSetSpec:
    return build_registry(environ={}).feature_set("paper8")


def bins_in(fs: float, low: float, high: float) -> list[float]:
    """FFT bin frequencies of one 0.64 s window inside [low, min(high, fs/2)], by hand."""
    n = round(0.64 * fs)
    return [k * fs / n for k in range(n // 2 + 1) if low <= k * fs / n <= min(high, fs / 2)]


def noise(fs: float, seconds: float = 4.0) -> np.ndarray:
    return np.random.default_rng(0).normal(size=round(seconds * fs))


def test_a_rate_leaving_the_band_empty_is_refused_naming_band_and_rate(paper8):
    with pytest.raises(SDTError) as info:
        extract(noise(15.0), 15.0, paper8)
    assert str(info.value).startswith(
        "feature set 'paper8': the band 10 Hz to Nyquist of A_RMS, A_Peak holds no FFT bin at "
        "fs=15 Hz (Nyquist 7.5 Hz, 10-sample windows), so those features would be 0; the rate "
        "must be above about 2 x 10 = 20 Hz"
    )


@pytest.mark.parametrize("fs", [float(f) for f in np.arange(15.0, 40.5, 0.5)])
def test_refused_exactly_when_a_band_holds_no_bin(paper8, fs):
    empty = not bins_in(fs, 10.0, np.inf) or not bins_in(fs, 10.0, 1000.0)
    if empty:
        with pytest.raises(SDTError, match=rf"holds no FFT bin at fs={fs:g} Hz"):
            extract(noise(fs), fs, paper8)
    else:
        table = extract(noise(fs), fs, paper8)
        frame = table.to_frame()
        for column in ("A_RMS", "A_Peak", "V_RMS", "D_RMS"):
            assert (frame[column] > 0).all(), (fs, column)


def test_the_refusal_covers_rates_on_both_sides_of_20_hz():
    # 21 Hz: 13-sample windows, highest bin 6 * 21 / 13 = 9.69 Hz < 10 Hz, so refused;
    # 25 Hz: 16-sample windows, bin 7 * 25 / 16 = 10.94 Hz inside the band, so accepted.
    assert bins_in(21.0, 10.0, 1000.0) == []
    assert bins_in(25.0, 10.0, 1000.0) == [10.9375, 12.5]


def test_composed_sets_keep_the_bands_of_their_parts(paper8):
    peak = FeatureSetSpec(
        name="peak",
        feature_names=("peak",),
        units=("g",),
        compute=lambda w, fs: np.abs(w).max(axis=1, keepdims=True),
    )
    with pytest.raises(SDTError, match="the band 10 Hz to Nyquist of A_RMS, A_Peak"):
        extract(noise(15.0), 15.0, compose([peak, paper8]))
    # a set declaring no band is not refused: the check follows the declaration
    assert extract(noise(15.0), 15.0, peak).values.shape == (5, 1)


def test_band_declarations_are_validated():
    from sdt_framework.specs import FeatureBand

    with pytest.raises(ValidationError, match="names unknown features"):
        FeatureSetSpec(
            name="x",
            feature_names=("a",),
            units=("g",),
            compute=lambda w, fs: w[:, :1],
            bands=(FeatureBand(features=("b",), low_hz=10),),
        )
    with pytest.raises(ValidationError, match="high_hz must be above low_hz"):
        FeatureBand(features=("a",), low_hz=10, high_hz=5)


def test_cli_refuses_the_rate_and_writes_nothing(tmp_path: Path, monkeypatch, capsys):
    np.save(tmp_path / "slow.npy", noise(15.0))
    out = tmp_path / "features.csv"
    args = ["sdt", "features", "extract", str(tmp_path / "slow.npy"), "--fs", "15"]
    monkeypatch.setattr(sys, "argv", [*args, "--out", str(out)])
    with pytest.raises(SystemExit) as info:
        main()
    assert info.value.code == 2
    err = capsys.readouterr().err
    start = f"error: {tmp_path / 'slow.npy'}: feature set 'paper8': the band 10 Hz"
    assert err.count("\n") == 1 and err.startswith(start)
    assert "fs=15 Hz" in err and "(--fs)" in err
    assert not out.exists()
