"""No module of the framework or its built-in plugins is over 300 lines (STYLE.md: modules
with one job, mostly 80-250 lines). A module that grows past it is split by job, as
``twin/check.py`` gave its result types to ``twin/results.py`` and its transfer to
``twin/transfer.py``."""

from __future__ import annotations

from pathlib import Path

import sdt_framework

REPO = Path(sdt_framework.__file__).parents[1]
#: the most lines a module may hold
MAX_LINES = 300


def long_modules(base: Path, *roots: Path, limit: int = MAX_LINES) -> list[str]:
    """``path: N lines`` (relative to ``base``) for each ``.py`` file under ``roots`` longer
    than ``limit``."""
    found = []
    for root in roots:
        for path in sorted(root.rglob("*.py")):
            lines = len(path.read_text(encoding="utf-8").splitlines())
            if lines > limit:
                found.append(f"{path.relative_to(base)}: {lines} lines")
    return found


def test_no_module_is_over_300_lines():
    roots = (REPO / "sdt_framework", REPO / "plugins")
    assert sum(1 for root in roots for _ in root.rglob("*.py")) > 300  # the tree, not nothing
    assert long_modules(REPO, *roots) == []


def test_the_count_is_the_files_lines(tmp_path):
    (tmp_path / "a.py").write_text("x = 1\n" * 301, encoding="utf-8")
    (tmp_path / "b.py").write_text("x = 1\n" * 300, encoding="utf-8")
    assert long_modules(tmp_path, tmp_path) == ["a.py: 301 lines"]
