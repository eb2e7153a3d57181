"""DC-only recordings: the report is written, Fig. 3 says why a panel is empty (issue 39, item 5).

On main a benchmark on recordings that are all ones (``np.ones_like``: a
sensor's offset and nothing else) ran its runs, then the report died of a
segmentation fault (exit 139, no report.md) inside scikit-learn's t-SNE: the
reference's features were identical in every window, the PCA start divided by
a zero spread and Barnes-Hut t-SNE crashed on NaN coordinates. A sensor whose
features do not vary (beyond rounding) now gets a panel saying so instead of
an embedding.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from sdt_framework.report.figures_features import plot_tsne

from ..helpers import MANIFEST_HEADER


def test_dc_only_recordings_get_their_report(sdt, tmp_path):
    lines = [MANIFEST_HEADER]
    for condition in ("healthy", "fault"):
        for index in range(3):
            name = f"{condition}{index}"
            np.save(tmp_path / f"{name}.npy", np.ones(40_000))  # 2 s at 20 kHz, 1 g DC
            severity = index + 1 if condition == "fault" else ""
            lines.append(f"{name}.npy,20000,m,{condition},{severity},{name},ch1\n")
    (tmp_path / "m.csv").write_text("".join(lines))
    out = tmp_path / "out"
    # a real process (the bug was a segmentation fault, exit 139), with --jobs 1: the t-SNE
    # is the report's, not the workers'; the results are the same at any --jobs
    done = sdt("benchmark", "--data", str(tmp_path / "m.csv"), "--quick", "--classifiers", "lr",
               "--jobs", "1", "--out", str(out))  # fmt: skip
    assert done.returncode == 0, (done.returncode, done.stderr[-2000:])
    report = (out / "report.md").read_text(encoding="utf-8")
    fig3 = report.split("### Fig. 3")[1].split("\n### ")[0]
    assert "fig3_tsne.png" in fig3 and "Not drawn" not in fig3
    assert (out / "figures" / "fig3_tsne.png").stat().st_size > 0


def _features(values: np.ndarray) -> pd.DataFrame:
    n = len(values)
    frame = pd.DataFrame(values, columns=[f"f{i}" for i in range(values.shape[1])])
    frame.insert(0, "sensor", "ref")
    frame.insert(0, "condition", ["healthy", "fault"] * (n // 2))
    return frame


def test_features_varying_by_rounding_only_are_not_embedded():
    """1 + 1e-15 noise: spread at rounding level; on main t-SNE embedded the noise."""
    rng = np.random.default_rng(0)
    values = 1.0 + 1e-15 * rng.normal(size=(40, 8))
    fig = plot_tsne(_features(values), ["ref"])
    panel = fig.axes[0]
    assert not panel.collections  # no points drawn
    assert [t.get_text() for t in panel.texts] == [
        "no feature varies over the 40 windows (constant or not finite)"
    ]


def test_varying_features_are_still_embedded():
    rng = np.random.default_rng(0)
    values = rng.normal(size=(40, 8))
    values[:, 3] = 2.0  # one constant feature is left out, the others embedded
    fig = plot_tsne(_features(values), ["ref"])
    offsets = np.vstack([c.get_offsets() for c in fig.axes[0].collections])
    assert offsets.shape == (40, 2) and np.isfinite(offsets).all()
