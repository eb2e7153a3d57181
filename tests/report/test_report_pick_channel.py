"""Fig. 2 shows the channel where the condition differs most from healthy (issue 40).

A campaign's NI channels are ``acc-ai0`` ... ``acc-ai3``, no ``ch1``: the old
rule took the first by name, the motor's axial channel, where a cavitation
test shows no cavitation.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from sdt_framework.data.recording import Recording
from sdt_framework.report.pick import channel_contrast, pick_recording

CHANNELS = ("acc-ai0", "acc-ai1", "acc-ai2", "acc-ai3")
#: per channel, how far (in standard deviations) cavitation moves A_RMS and K
SHIFTS = {"acc-ai0": (0.2, 0.1), "acc-ai1": (1.0, 0.5), "acc-ai2": (3.0, 6.0), "acc-ai3": (4.0, 1)}


def _recording(condition: str, severity: int | None, run: str, channel: str) -> Recording:
    return Recording(
        "manifest", "Motor-4", None, condition, severity, run, channel, f"{run}/{channel}",
        25600.0, "g", 1, 1024, (0,), "daq.tdms", lambda: np.zeros((1, 1024)),
    )  # fmt: skip


def _campaign() -> tuple[list[Recording], pd.DataFrame]:
    rng = np.random.default_rng(0)
    recordings, rows = [], []
    tests = [("healthy", None, f"healthy_{k}") for k in range(3)]
    tests += [("cavitation suction", n, f"cav_{n}_{k}") for n in (1, 4) for k in range(3)]
    for condition, severity, run in tests:
        for channel in CHANNELS:
            recordings.append(_recording(condition, severity, run, channel))
            shift = np.array(SHIFTS[channel]) * (severity == 4)
            for window in range(20):
                a_rms, kurt = rng.normal(size=2) + shift
                rows.append(
                    {
                        "machine": "Motor-4", "run": run, "condition": condition,
                        "severity": severity, "channel": channel,
                        "recording_id": f"{run}/{channel}", "sensor": "native-reference",
                        "repeat": 0, "acquisition": 0, "window": window,
                        "A_RMS": 1 + 0.1 * a_rms, "K": 3 + 0.2 * kurt,
                    }
                )  # fmt: skip
    return recordings, pd.DataFrame(rows)


def test_fig2_shows_the_channel_where_the_condition_differs_most_from_healthy() -> None:
    recordings, features = _campaign()
    choice = pick_recording(recordings, features, "native-reference")
    assert choice.recording.condition == "cavitation suction" and choice.recording.severity == 4
    # independent: every channel's distance, recomputed from the windows with pandas
    level4 = features["severity"] == 4
    healthy = features["severity"].isna()
    best = {}
    for channel, part in features.groupby("channel"):
        c, h = part[level4[part.index]], part[healthy[part.index]]
        d = {
            f: abs(c[f].mean() - h[f].mean()) / np.sqrt((c[f].var() + h[f].var()) / 2)
            for f in ("A_RMS", "K")
        }
        best[channel] = max(d.items(), key=lambda item: item[1])
    expected = max(best, key=lambda ch: best[ch][1])
    assert expected == "acc-ai2"  # K moved by 6 SDs there, the largest shift built in
    assert choice.recording.channel == expected  # the old rule took acc-ai0
    feature, distance = best[expected]
    assert f"{expected}, where cavitation suction 4 differs most from healthy" in choice.reason
    assert f"feature {feature} {distance:.1f} pooled SDs apart" in choice.reason
    table = channel_contrast(features, "native-reference", "Motor-4", "cavitation suction", 4)
    assert list(table["channel"]) == sorted(best, key=lambda ch: -best[ch][1])


def test_fig2_without_features_says_it_chose_by_name() -> None:
    recordings, _ = _campaign()
    choice = pick_recording(recordings)
    assert choice.recording.channel == "acc-ai0"
    assert choice.reason.startswith("acc-ai0 by name (no healthy and fault windows")
