"""A time base that is not one record is refused, not resampled (issue 29, B7).

One data block of channel 32 (the ADXL345) of ``SSX66115.IDE`` stamped 1 s early
is read by idelib as a clock wrap: 511 s later. A straight line through those
timestamps gives a 64 Hz "rate" for a 3134 Hz part, and every figure after it is
wrong. The refusal must name the channel, the sample index and the jump. The
block is moved by rewriting its two time codes in place (32768 ticks a second,
the recorder's time scalar), on a copy in a temporary folder.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sdt_framework.errors import SDTError
from sdt_framework.signals.timebase import on_even_grid, require_one_record

DATA = Path(__file__).parents[1] / "data" / "endaq"
TICKS_PER_S = 32768  # SSX66115's time codes: 30.517578125 us each
BLOCK = 30  # the 31st block of channel 32, from 3.74 s


#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


SAMPLES_PER_BLOCK = 390  # 2340 payload bytes, 3 axes of 2 bytes


def _block_moved_back(folder: Path) -> Path:
    from idelib.importer import openFile

    data = bytearray((DATA / "SSX66115.IDE").read_bytes())
    with open(DATA / "SSX66115.IDE", "rb") as stream:
        blocks = [
            {child.name: child for child in element}
            for element in openFile(stream, quiet=True).ebmldoc
            if element.name == "ChannelDataBlock"
        ]
        ours = [b for b in blocks if b["ChannelIDRef"].value == 32]
        for code in ("StartTimeCodeAbs", "EndTimeCodeAbs"):
            at, size = ours[BLOCK][code].payloadOffset, ours[BLOCK][code].size
            value = int.from_bytes(data[at : at + size], "big") - TICKS_PER_S
            data[at : at + size] = value.to_bytes(size, "big")
    path = folder / "back.IDE"
    path.write_bytes(bytes(data))
    return path


def test_a_constructed_clock_step_is_refused_naming_the_sample_and_the_jump():
    rate = 3134.0
    times = np.arange(40_000) / rate
    times[11_700:] += 511.0  # what idelib makes of a block stamped 1 s early
    with pytest.raises(SDTError) as caught:
        on_even_grid(times, np.zeros((1, times.size)), "rec.IDE channel 32")
    message = str(caught.value)
    assert message.startswith("rec.IDE channel 32: timestamps jump by 511 s")
    assert f"({511 * rate + 1:,.0f} sample periods)" in message
    assert "between samples 11,699 and 11,700" in message


def test_a_timestamp_that_goes_back_or_a_rate_that_changes_is_refused():
    times = np.arange(1000) / 1000.0
    times[500:] -= 0.2
    with pytest.raises(SDTError, match=r"go back by 0.199 s .* between samples 499 and 500"):
        require_one_record(times, "x")
    # 3000 samples at 1600 Hz, then 5000 at 3200 Hz: no interval longer than two periods,
    # but no one rate either: the median interval gives 3200 Hz, a line through all ~2430 Hz
    changing = np.concatenate([np.arange(3000) / 1600, 3000 / 1600 + np.arange(1, 5001) / 3200])
    with pytest.raises(SDTError, match="the rate changes within the recording"):
        require_one_record(changing, "x")


def test_real_recorders_time_bases_are_one_record():
    """Every channel of the shipped recordings passes (their intervals are within 17 % of the
    median and their two rates within 2.4 %), and their accelerometers read as before."""
    from sdt_plugins.readers.ide.parse import inspect_ide, read_ide

    for path in sorted(DATA.glob("*.IDE")):
        assert [c.time_fault for c in inspect_ide(path)] == [None] * len(inspect_ide(path))
    assert read_ide(DATA / "DAQ12006_000005.IDE", 80).rate_hz == pytest.approx(4038.58, abs=0.01)


def test_inspect_shows_the_channel_and_warns(sdt, tmp_path):
    run = sdt("dataset", "inspect", str(_block_moved_back(tmp_path)))
    assert run.returncode == 0, run.stderr
    assert run.stderr.startswith("warning: channel 32: timestamps jump by 511 s")


@pytest.mark.parametrize(
    "command",
    [["twin", "check", "{}", "--sensor", "adxl345"],
     ["validate-noise", "--sensor", "adxl345", "--axis", "x", "--recording", "{}"]],
    ids=["check", "validate-noise"],
)  # fmt: skip
def test_an_ide_block_stamped_a_second_early_is_refused(sdt, tmp_path, command):
    path = _block_moved_back(tmp_path)
    run = sdt(*[part.format(path) for part in command])
    assert run.returncode == 2, run.stdout
    assert run.stderr.startswith("error:") and run.stderr.count("\n") == 1, run.stderr
    first = BLOCK * SAMPLES_PER_BLOCK  # the moved block's first sample
    assert "back.IDE channel 32: timestamps jump by" in run.stderr
    assert f"between samples {first - 1:,} and {first:,}" in run.stderr
