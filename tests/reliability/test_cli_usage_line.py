"""A mistyped command line is one ``error:`` line and exit 2, like every other bad input.

Before, click's parser printed five lines for these: ``Usage: ...``, ``Try 'sdt ... --help'``
and a boxed error. The commands are refused while their options are parsed, before any
work, so they run in this process (``in_process``).
"""

from __future__ import annotations

import pytest

pytestmark = pytest.mark.in_process

CASES = [
    (("budget", "--axes", "abc"), ("'--axes'", "valid integer", "see sdt budget --help")),
    (("benchmark", "--repeats", "abc"), ("'--repeats'", "see sdt benchmark --help")),
    (("benchmark", "--nosuch"), ("No such option: --nosuch", "see sdt benchmark --help")),
    (("nosuchcmd",), ("No such command 'nosuchcmd'", "see sdt --help")),
    (("--nosuch", "sensors", "list"), ("No such option: --nosuch", "see sdt --help")),
    (("sensors", "show"), ("Missing argument 'name'", "see sdt sensors show --help")),
    (("twin", "check", "x.IDE", "--nosuch"), ("--nosuch", "see sdt twin check --help")),
]


@pytest.mark.parametrize(("args", "words"), CASES, ids=lambda v: " ".join(v)[:40])
def test_a_mistyped_command_line_is_one_error_line(sdt, args, words):
    done = sdt(*args)
    assert done.returncode == 2
    assert done.stdout == ""
    lines = done.stderr.splitlines()
    assert len(lines) == 1, done.stderr
    assert lines[0].startswith("error: ")
    for word in words:
        assert word in lines[0]


@pytest.mark.parametrize("args", [(), ("sensors",)], ids=["sdt", "sdt sensors"])
def test_a_command_or_group_alone_still_prints_its_help(sdt, args):
    done = sdt(*args)
    shown = done.stdout + done.stderr
    assert "Usage: " in shown
    assert "error:" not in shown
