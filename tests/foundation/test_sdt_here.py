"""``sdt_here`` (tests/helpers.py) gives what ``run_sdt``'s child process gives, for the
tests that run their set-up and follow-up commands in the test's process."""

from __future__ import annotations

import warnings

import sdt_framework.cli.entry as entry

from ..helpers import run_sdt, sdt_here


def test_a_command_gives_the_childs_status_and_output(tmp_path):
    """A refused input: the same exit status, stdout and stderr as a real process."""
    args = ("sensors", "show", "no-such-part")
    here, child = sdt_here(*args), run_sdt(*args)
    assert (here.returncode, here.stdout, here.stderr) == (
        child.returncode,
        child.stdout,
        child.stderr,
    )
    assert here.returncode == 2 and here.stderr.startswith("error: ")


def test_a_raw_python_warning_reaches_stderr_as_in_a_child(monkeypatch):
    """pytest records warnings out of sight; a command's raw warning must still show, as
    it would on a user's terminal, so a test asserting a clean stderr can fail."""

    def main() -> None:
        from sdt_framework.cli.failures import run

        run(lambda: warnings.warn("invalid value", RuntimeWarning, stacklevel=1))

    monkeypatch.setattr(entry, "main", main)
    done = sdt_here("anything")
    assert done.returncode == 0
    assert "RuntimeWarning: invalid value" in done.stderr
