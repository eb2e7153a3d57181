"""Shared fixtures: fake installed distributions, built in a temp folder.

Following flake8's approach, a test that needs a third-party plugin writes a
module and a ``*.dist-info`` folder with ``entry_points.txt`` into a temporary
directory on ``sys.path``; importlib.metadata then finds it exactly as it would
find a pip-installed distribution.
"""

from __future__ import annotations

import importlib
import sys
import textwrap
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from sdt_framework import build_registry
from sdt_framework.cli.main import main

FakeDist = Callable[..., Path]


@pytest.fixture
def fake_dist(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[FakeDist]:
    """Factory: ``fake_dist("dist-name", {"ep-name": "module"}, {"module": "source"})``."""
    root = tmp_path / "site"
    root.mkdir()
    monkeypatch.syspath_prepend(str(root))
    added: list[str] = []

    def make(dist: str, entry_points: dict[str, str], modules: dict[str, str]) -> Path:
        for module, source in modules.items():
            (root / f"{module}.py").write_text(textwrap.dedent(source))
            added.append(module)
        info = root / f"{dist.replace('-', '_')}-1.2.3.dist-info"
        info.mkdir()
        (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {dist}\nVersion: 1.2.3\n")
        lines = "\n".join(f"{name} = {target}" for name, target in entry_points.items())
        (info / "entry_points.txt").write_text(f"[sdt_framework]\n{lines}\n")
        importlib.invalidate_caches()
        return root

    yield make
    for module in added:
        sys.modules.pop(module, None)


@pytest.fixture(scope="session")
def registry():
    """The installed registry (built-in plugins), shared: a test that adds specs builds its own."""
    return build_registry()


@pytest.fixture
def sdt_main(monkeypatch, capsys):
    """``sdt_main(*args)``: ``main()`` in this process: (exit status, stdout, stderr)."""

    def run(*args: str) -> tuple[int, str, str]:
        monkeypatch.setattr(sys, "argv", ["sdt", *args])
        try:
            main()
            code = 0
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else 1
        out = capsys.readouterr()
        return code, out.out, out.err

    return run
