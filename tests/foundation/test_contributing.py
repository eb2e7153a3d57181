"""CONTRIBUTING.md names only files and folders that exist."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
#: a backticked repository path: a folder ending in / or a file with a suffix
PATH = re.compile(r"`([\w./-]+/|[\w./-]+\.(?:py|toml|md))`")


def test_every_path_it_names_exists():
    text = (ROOT / "CONTRIBUTING.md").read_text(encoding="utf-8")
    paths = set(PATH.findall(text))
    assert len(paths) >= 20  # every row of the table names a file to copy
    missing = [p for p in paths if not (ROOT / p).exists()]
    assert missing == []
