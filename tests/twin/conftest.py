"""``sdt_main``: the ``sdt`` command run in this process (exit status, stdout, stderr)."""

from __future__ import annotations

import sys

import pytest

from sdt_framework.cli.main import main


@pytest.fixture
def sdt_main(monkeypatch, capsys):
    """``sdt_main(*args)`` -> (exit status, stdout, stderr), as ``sdt`` would print them."""

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
