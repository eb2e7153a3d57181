"""A user's bad input met in a worker process is its one line and exit 2, never exit 70.

Before, a ``ChainInputError`` raised in a loky worker could not be rebuilt in the
main process (its ``__init__`` takes three arguments) and every such error
became ``internal error: BrokenProcessPool`` (exit 70) with the default
``--jobs``; ``--jobs 1`` printed the right line. The case that showed it: a
recording with no sample or one (a TDMS channel, or an ``.npy``), which the
plan now refuses before any work; the transport is tested with that check
switched off, so the error is raised where any other would be, in a worker.
"""

from __future__ import annotations

import numpy as np
import pytest

from ..helpers import six_recordings


@pytest.fixture
def one_sample(tmp_path):
    """The six-recording manifest, its ``fault1.npy`` replaced by a single sample."""
    manifest = six_recordings(tmp_path)
    np.save(tmp_path / "fault1.npy", np.array([0.25]))
    return manifest


def _tdms(path, samples: int) -> None:
    """One channel of ``samples`` values at 20 kHz in g, as a DAQ writes it."""
    from nptdms import ChannelObject, TdmsWriter

    props = {"wf_increment": 1 / 20_000, "unit_string": "g"}
    with TdmsWriter(path) as writer:
        writer.write_segment([ChannelObject("ai0", "acc", np.full(samples, 0.25), props)])


# (a TDMS channel with no sample is refused by the TDMS reader as the manifest is opened)
@pytest.mark.parametrize(
    ("suffix", "samples"), [("npy", 0), ("npy", 1), ("npy", 14_799), ("tdms", 1)]
)
def test_a_recording_shorter_than_one_window_is_refused_before_any_work(
    tmp_path, sdt_main, suffix, samples
):
    manifest = six_recordings(tmp_path)
    if suffix == "tdms":  # the case: a TDMS channel of one sample
        _tdms(tmp_path / "fault1.tdms", samples)
        text = manifest.read_text().replace("fault1.npy,20000", "fault1.tdms,")
        manifest.write_text(text)
    else:
        np.save(tmp_path / "fault1.npy", np.full(samples, 0.25))
    code, _, err = sdt_main(
        "benchmark", "--data", str(manifest), "--quick", "--classifiers", "lr", "--jobs", "2",
        "--no-report", "--out", str(tmp_path / "out"), "--cache-dir", str(tmp_path / "cache"),
    )  # fmt: skip
    assert code == 2 and "Traceback" not in err, err
    # 0.1 s settling + 0.64 s window at the reference's 20 kHz: 2000 + 12800 samples
    plural = "" if samples == 1 else "s"
    assert err.splitlines() == [
        f"error: recording m/fault1/ch1 ({tmp_path / f'fault1.{suffix}'}) holds {samples:,} "
        f"sample{plural} per acquisition ({samples / 20000:.4g} s at 20000 Hz), shorter than one "
        f"0.64 s window after 0.1 s settling (0.74 s: wilcoxon-786b10 needs 14,800 samples at "
        f"20000 Hz); leave it out of the data or give a longer recording"
    ]
    assert not (tmp_path / "out").exists() and not (tmp_path / "cache" / "features").exists()


BACKENDS = {"loky": ["--jobs", "2"], "dask": ["--backend", "dask", "--jobs", "2"]}


@pytest.mark.parametrize("backend", sorted(BACKENDS))
def test_a_workers_bad_input_line_reaches_the_user(
    tmp_path, sdt_main, monkeypatch, one_sample, backend
):
    # the plan's length check off: the recording reaches a worker, whose chain refuses it
    monkeypatch.setattr("sdt_framework.bench.plan.check_lengths", lambda *a: None, raising=False)
    code, _, err = sdt_main(
        "benchmark", "--data", str(one_sample), "--quick", "--classifiers", "lr",
        *BACKENDS[backend], "--no-report", "--out", str(tmp_path / "out"),
        "--cache-dir", str(tmp_path / "cache"),
    )  # fmt: skip
    assert code == 2 and "Traceback" not in err and "internal error" not in err, err
    errors = [line for line in err.splitlines() if line.startswith("error:")]
    assert errors == [
        f"error: sensor 'wilcoxon-786b10', recording '{tmp_path / 'fault1.npy'} (m/fault1/ch1)': "
        f"1 sample per acquisition; at least 2 are needed"
    ]
