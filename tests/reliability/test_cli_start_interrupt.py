"""Ctrl-C while ``sdt`` is still loading its modules: one line and exit 130, no traceback.

The console script's own import must be cheap for that (the package root loads
its public names on first use), so the guard in ``sdt_framework.cli.entry`` is in
place before numpy, pandas and the subcommands load.
"""

from __future__ import annotations

import importlib.abc
import subprocess
import sys
from importlib.metadata import entry_points

import pytest

from sdt_framework.cli import entry


class _CtrlCOnImport(importlib.abc.MetaPathFinder):
    """Raise KeyboardInterrupt when ``name`` is imported, as a Ctrl-C during its load does."""

    def __init__(self, name: str) -> None:
        self.name = name

    def find_spec(self, fullname: str, path: object, target: object = None) -> None:
        if fullname == self.name:
            raise KeyboardInterrupt
        return None


def test_ctrl_c_while_the_commands_load_is_one_line_and_exit_130(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.delitem(sys.modules, "sdt_framework.cli.main", raising=False)
    monkeypatch.setattr(
        sys, "meta_path", [_CtrlCOnImport("sdt_framework.cli.main"), *sys.meta_path]
    )
    with pytest.raises(SystemExit) as stop:
        entry.main()
    assert stop.value.code == 130
    err = capsys.readouterr().err
    assert err.startswith("interrupted:") and err.count("\n") == 1 and "Traceback" not in err


def test_the_console_script_and_python_m_start_through_the_guard() -> None:
    (script,) = [e for e in entry_points(group="console_scripts") if e.name == "sdt"]
    assert script.value == "sdt_framework.cli.entry:main"
    main_module = subprocess.run(
        [sys.executable, "-c", "import runpy, sys; sys.argv = ['sdt', '--help'];"
         "runpy.run_module('sdt_framework', run_name='__main__')"],
        capture_output=True, text=True, check=False,
    )  # fmt: skip
    assert main_module.returncode == 0 and "Usage" in main_module.stdout


def test_importing_the_package_loads_no_heavy_dependency() -> None:
    # what runs before the guard: the package root and the entry module
    code = (
        "import sys, sdt_framework.cli.entry; "
        "print(sorted({m.split('.')[0] for m in sys.modules} & "
        "{'numpy', 'pandas', 'pydantic', 'pluggy', 'typer', 'sklearn', 'scipy'}))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_every_public_name_of_the_lazy_package_root_resolves() -> None:
    # the names the package lists and the names it loads on first use are the same set
    import sdt_framework

    assert set(sdt_framework.__all__) == {*sdt_framework._SOURCES, "__version__"}
    for name in sdt_framework.__all__:
        assert getattr(sdt_framework, name) is not None
