"""A bug in sdt is told apart from a user's mistake: its own line, exit 70, a traceback on demand.

The bug is forced through the real command: a tiny plugin, installed in a
temporary site folder, replaces a function ``sdt sensors list`` calls with
one that divides by zero (an exception no code path of sdt expects), or
raises :class:`~sdt_framework.errors.InternalError`. Before, such an
exception was either Python's bare traceback (exit 1) or, for sdt's own
"no registry bound" check, a one-line ``error:`` with exit 2, the same as a
typo in a sensor name.

The commands run in this process (``in_process``; ``fake_dist`` puts the site on
``sys.path`` here as well): the plugin's replacement of ``_profile_row`` is undone
after each test, so no later command in this process meets it.
"""

from __future__ import annotations

import os

import pytest

import sdt_framework.cli.sensors as listing
from sdt_framework.errors import INTERNAL_EXIT

pytestmark = pytest.mark.in_process

PLUGIN = """
import sdt_framework.cli.sensors as listing
from sdt_framework.errors import InternalError


def _divides_by_zero(sensor):
    return 1 / 0


def _broken_invariant(sensor):
    raise InternalError("a state sdt never reaches")


listing._profile_row = {kind}


def register_sensors(register):
    pass
"""


@pytest.fixture(autouse=True)
def _profile_row_restored(monkeypatch):
    """The plugin replaces ``listing._profile_row`` when imported: put back after the test."""
    monkeypatch.setattr(listing, "_profile_row", listing._profile_row)


def _run(sdt, fake_dist, kind: str, **env: str):
    root = fake_dist(
        "buggy-plugin", {"buggy": "buggy_plugin"}, {"buggy_plugin": PLUGIN.format(kind=kind)}
    )
    path = os.pathsep.join(filter(None, [str(root), os.environ.get("PYTHONPATH")]))
    return sdt("sensors", "list", env={"PYTHONPATH": path, **env})


@pytest.mark.parametrize(
    ("kind", "shown"),
    [
        ("_divides_by_zero", "ZeroDivisionError: division by zero"),
        ("_broken_invariant", "InternalError: a state sdt never reaches"),
    ],
)
def test_a_bug_is_an_internal_error_with_exit_70(sdt, fake_dist, kind, shown):
    done = _run(sdt, fake_dist, kind)
    assert done.returncode == INTERNAL_EXIT == 70
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1, done.stderr  # no traceback unless asked for
    line = lines[0]
    assert line.startswith("internal error: ") and not line.startswith("error:")
    assert shown in line
    assert "this is a bug in sdt" in line
    assert "SDT_DEBUG=1 sdt sensors list" in line
    assert "buggy_plugin.py" in line  # where it was raised


def test_sdt_debug_shows_the_traceback_of_an_internal_error(sdt, fake_dist):
    done = _run(sdt, fake_dist, "_divides_by_zero", SDT_DEBUG="1")
    assert done.returncode == 70
    assert "Traceback (most recent call last)" in done.stderr
    assert "return 1 / 0" in done.stderr  # the faulty line itself
    assert done.stderr.strip().splitlines()[-1].startswith("internal error: ZeroDivisionError")


def test_sdt_debug_shows_the_traceback_of_a_user_error_too(sdt):
    done = sdt("sensors", "show", "no-such-sensor", env={"SDT_DEBUG": "1"})
    assert done.returncode == 2
    assert "Traceback (most recent call last)" in done.stderr
    assert "UnknownNameError" in done.stderr
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("error: unknown sensor 'no-such-sensor'")
    plain = sdt("sensors", "show", "no-such-sensor")
    assert plain.returncode == 2 and "Traceback" not in plain.stderr
