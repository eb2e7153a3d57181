"""Errors quote at most a short token of a file's content, never a whole line.

On main before the reliability round a manifest row pointing (through a
symlink) at a system file put a whole line of that file into the skip
reason, hence into ``skipped.csv`` and ``summary.json`` of a results folder,
and ``sdt degrade`` printed one on the terminal. The "system file" here is a
stand-in written by the test, with lines long and short.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from sdt_framework.data import open_manifest

#: the promise: at most this many consecutive characters of a file's content in a message
TOKEN_LIMIT = 20
SECRET = [
    "root:x:0:0:root:/root:/bin/bash",
    "svc-backup:$6$Zx81Qe$Vb5oLq7Yt0cXk3pWn9Ha2sEe4Rf:19000:0:99999:7:::",
    "api_token=9f8e7d6c5b4a39281706f5e4d3c2b1a0",
]


@pytest.fixture
def secret(tmp_path: Path) -> Path:
    path = tmp_path / "system" / "shadow"
    path.parent.mkdir()
    path.write_text("\n".join(SECRET) + "\n")
    return path


def leaks(text: str) -> list[str]:
    """Pieces of the secret longer than TOKEN_LIMIT characters found in ``text``."""
    n = TOKEN_LIMIT + 1
    return [
        line[i : i + n]
        for line in SECRET
        for i in range(len(line) - n + 1)
        if line[i : i + n] in text
    ]


def test_quote_cuts_long_tokens() -> None:
    from sdt_framework.signals.tokens import quote

    assert quote("1.25") == "'1.25'"
    assert quote(SECRET[1]) == repr(SECRET[1][:TOKEN_LIMIT] + "…")


@pytest.mark.parametrize("suffix", [".csv", ".npy", ".mat"])
def test_manifest_row_pointing_at_a_system_file(
    tmp_path: Path, secret: Path, suffix: str, readers
) -> None:
    link = tmp_path / f"signal{suffix}"
    link.symlink_to(secret)
    manifest = tmp_path / "m.csv"
    manifest.write_text(
        "path,sampling_rate_hz,condition,severity,recording_id,channel\n"
        f"{link.name},1000,healthy,,r1,ch1\n"
    )
    ds = open_manifest(manifest, readers=readers, validate=True)
    assert ds.recordings() == [] and len(ds.skipped) == 1
    reason = json.dumps(ds.describe())
    assert leaks(reason) == [], reason


def test_manifest_symlinked_to_a_system_file(tmp_path: Path, secret: Path, readers) -> None:
    link = tmp_path / "manifest.csv"
    link.symlink_to(secret)
    with pytest.raises(Exception) as info:
        open_manifest(link, readers=readers)
    assert leaks(str(info.value)) == [], str(info.value)


def test_degrade_of_a_system_file(
    sdt_main, monkeypatch, capsys, tmp_path: Path, secret: Path
) -> None:
    link = tmp_path / "in.csv"
    link.symlink_to(secret)
    code, out, err = sdt_main(
        *("degrade", str(link), "--sensor", "adxl345", "--fs", "20000"),
        *("--out", str(tmp_path / "o.npy")),
    )
    assert code == 2 and err.count("\n") == 1
    assert leaks(out + err) == [], err


def test_nln_emp_header_is_not_quoted_whole(tmp_path: Path, secret: Path) -> None:
    from sdt_plugins.datasets.nln_emp import open_nln_emp

    folder = tmp_path / "Vibration" / "Motor-4" / "70" / "healthy 1"
    folder.mkdir(parents=True)
    (folder / "Vibration_Motor-4_70_time-healthy 1-ch1.csv").symlink_to(secret)
    ds = open_nln_emp(tmp_path, cache=False)
    assert len(ds.skipped) == 1 and "line 1: header" in ds.skipped[0].reason
    assert leaks(json.dumps(ds.describe())) == []
