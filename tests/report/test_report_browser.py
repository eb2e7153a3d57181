"""report.html in a real headless Chromium: renders, no console errors, every figure decodes.

Skipped, with the reason printed, when no Chromium/Chrome binary is installed
(``make test`` installs one in CI when it can).
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from matplotlib import image

BROWSERS = ("chromium", "chromium-browser", "google-chrome")
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--enable-logging=stderr",
    "--v=0",
]


@pytest.fixture(scope="module")
def browser() -> str:
    found = next((shutil.which(name) for name in BROWSERS if shutil.which(name)), None)
    if found is None:
        reason = f"no headless browser found ({', '.join(BROWSERS)}): browser test skipped"
        print(reason)
        pytest.skip(reason)
    return found


def _run(browser: str, tmp: Path, *args: str) -> subprocess.CompletedProcess[str]:
    profile = tmp / f"profile-{len(list(tmp.iterdir()))}"
    return subprocess.run(
        [browser, *FLAGS, f"--user-data-dir={profile}", *args],
        capture_output=True,
        text=True,
        timeout=120,
    )


def _errors(stderr: str) -> list[str]:
    return [
        line
        for line in stderr.splitlines()
        if "CONSOLE" in line or "Uncaught" in line or "Failed to load resource" in line
    ]


def test_report_renders_without_errors(browser, full_report, tmp_path):
    _, written = full_report
    shot = tmp_path / "shot.png"
    done = _run(
        browser,
        tmp_path,
        f"--screenshot={shot}",
        "--window-size=1280,2000",
        written["html"].as_uri(),
    )
    assert shot.is_file(), done.stderr[-2000:]
    assert not _errors(done.stderr), _errors(done.stderr)
    pixels = image.imread(shot)[..., :3]
    assert pixels.shape[:2] == (2000, 1280)
    assert (pixels < 0.5).any(axis=2).mean() > 0.005  # text and tables were drawn


def test_every_embedded_figure_decodes(browser, full_report, tmp_path):
    """A copy of the report with a probe script that lists each image's decoded size."""
    _, written = full_report
    probe = (
        "<script>window.addEventListener('load',()=>{const p=document.createElement('pre');"
        "p.id='probe';p.textContent=[...document.images].map(i=>i.naturalWidth+'x'+"
        "i.naturalHeight).join(' ');document.body.appendChild(p);});</script></body>"
    )
    page = tmp_path / "probe.html"
    page.write_text(written["html"].read_text(encoding="utf-8").replace("</body>", probe))
    done = _run(browser, tmp_path, "--virtual-time-budget=5000", "--dump-dom", page.as_uri())
    match = re.search(r'<pre id="probe">([^<]*)</pre>', done.stdout)
    assert match, done.stderr[-2000:]
    sizes = [tuple(map(int, s.split("x"))) for s in match.group(1).split()]
    assert len(sizes) == written["html"].read_text(encoding="utf-8").count("<img ") >= 5
    assert all(w > 400 and h > 300 for w, h in sizes), sizes
    assert np.all(np.array(sizes) > 0)
