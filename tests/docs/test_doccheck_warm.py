"""A documented ``sdt`` started warm prints, exits and ends as a fresh process would.

The checker's server (``tools/doccheck/warm.py``) forks each command from a
process that has the scientific stack loaded. These tests hold it to the
fresh ``sdt``: the same output and status; and, asked of the server itself,
the command's status and CPU come back, a relayed signal arrives, and a
command whose client was killed (a timeout) is killed with its session.
"""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from tools.doccheck.warm import WarmStart

COMMANDS = [
    "sdt sensors list --max-price 15EUR",
    "sdt sensors list | head -2",  # the pipe closes before sdt is done
    "sdt benchmark nosuch.toml",  # one error line, exit 2
    "sdt budget --axes abc",  # click's usage error
    "echo 'x: 1' > s.toml; sdt --sensor-file s.toml sensors list",  # a bad file, folder-relative
    "COLUMNS=60 sdt sensors list --max-price 15EUR",  # the width of this command, not the server's
]


@pytest.fixture(scope="module")
def warm():
    with WarmStart() as server:
        yield server


def _bash(command: str, env: dict[str, str], folder: Path) -> subprocess.CompletedProcess:
    return subprocess.run(
        ["bash", "-c", command], env=env, cwd=folder, capture_output=True, text=True, check=False
    )


@pytest.mark.parametrize("command", COMMANDS)
def test_a_warm_command_prints_and_exits_as_a_fresh_one(warm, command, tmp_path):
    base = {**os.environ, "COLUMNS": "100", "NO_COLOR": "1", "TERM": "dumb"}
    base["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{base['PATH']}"
    (tmp_path / "cold").mkdir()
    (tmp_path / "warm").mkdir()
    cpu = tmp_path / "cpu.txt"
    cold = _bash(command, base, tmp_path / "cold")
    hot_env = warm.environment({**base, "SDT_WARM_CPU_FILE": str(cpu)})
    hot = _bash(command, hot_env, tmp_path / "warm")
    assert (hot.returncode, hot.stdout, hot.stderr) == (cold.returncode, cold.stdout, cold.stderr)
    assert cpu.read_text().strip(), "the command did not go through the warm server"


def test_without_a_server_the_client_runs_the_installed_sdt(warm, tmp_path):
    env = {k: v for k, v in os.environ.items() if k != "SDT_WARM_SOCKET"}
    env["SDT_WARM_CPU_FILE"] = str(tmp_path / "cpu.txt")
    done = subprocess.run(
        [warm.bin / "sdt", "--help"], env=env, capture_output=True, text=True, check=False
    )
    assert done.returncode == 0 and "Usage" in done.stdout
    assert not (tmp_path / "cpu.txt").exists()


def _ask(warm: WarmStart, script: Path, out: Path) -> socket.socket:
    """Start ``python script`` through the server as the client does; stdout into ``out``."""
    link = socket.socket(socket.AF_UNIX, socket.SOCK_SEQPACKET)
    link.connect(str(warm.address))
    request = {"argv": [str(script)], "cwd": str(script.parent), "env": dict(os.environ),
               "ignored": []}  # fmt: skip
    with open(os.devnull) as stdin, out.open("w") as stdout:
        fds = [stdin.fileno(), stdout.fileno(), stdout.fileno()]
        socket.send_fds(link, [json.dumps(request).encode()], fds)
    return link


def test_the_server_returns_the_status_and_cpu_of_its_command(warm, tmp_path):
    script = tmp_path / "burn.py"
    script.write_text(
        "import sys, time\nt = time.process_time()\n"
        "while time.process_time() - t < 0.3:\n    pass\nprint('burnt')\nsys.exit(3)\n"
    )
    link = _ask(warm, script, tmp_path / "out.txt")
    reply = json.loads(link.recv(4096))
    assert reply["status"] == 3
    assert 0.3 <= reply["cpu"] < 5
    assert (tmp_path / "out.txt").read_text() == "burnt\n"


def test_a_relayed_signal_reaches_the_command(warm, tmp_path):
    script = tmp_path / "wait.py"
    script.write_text(
        "import signal, sys, time\n"
        "signal.signal(signal.SIGTERM, lambda *_: (print('term'), sys.exit(7)))\n"
        "open('started', 'w').close()\ntime.sleep(60)\n"
    )
    link = _ask(warm, script, tmp_path / "out.txt")
    _wait_for(tmp_path / "started")
    link.send(b"15")
    assert json.loads(link.recv(4096))["status"] == 7
    assert (tmp_path / "out.txt").read_text() == "term\n"


def test_a_command_whose_client_is_gone_is_killed(warm, tmp_path):
    script = tmp_path / "sleep.py"
    script.write_text("import os, time\nopen('pid', 'w').write(str(os.getpid()))\ntime.sleep(60)\n")
    link = _ask(warm, script, tmp_path / "out.txt")
    _wait_for(tmp_path / "pid")
    pid = int((tmp_path / "pid").read_text())
    link.close()  # as when a timeout kills the shell and its client
    deadline = time.monotonic() + 10
    while Path(f"/proc/{pid}").exists() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not Path(f"/proc/{pid}").exists(), "the command outlived its client"


def _wait_for(path: Path) -> None:
    deadline = time.monotonic() + 20
    while not path.exists() and time.monotonic() < deadline:
        time.sleep(0.02)
    assert path.exists(), f"{path.name} never appeared"


def test_the_server_loads_sdt_and_its_plugins_but_never_its_command_line():
    """sdt's command line builds rich's consoles as it loads, and they would keep the server's
    ``COLUMNS``; the rest of sdt and its plugins are loaded once, for every command."""
    code = (
        "import json, sys; from tools.doccheck.warm import _preload; _preload(); "
        "print(json.dumps(sorted(m for m in sys.modules if m.startswith('sdt'))))"
    )
    root = Path(__file__).resolve().parents[2]
    env = {**os.environ, "COLUMNS": "33"}
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=root, env=env, capture_output=True, text=True, check=True
    )
    loaded = set(json.loads(done.stdout))
    assert {"sdt_framework.bench", "sdt_framework.report", "sdt_plugins.sensors.adxl345"} <= loaded
    assert not [m for m in loaded if m.startswith("sdt_framework.cli")]


def test_where_no_server_can_start_every_command_starts_fresh_with_one_note(monkeypatch, capsys):
    """The checker and the suite's documented commands share one fallback (``warm_or_cold``)."""
    import contextlib

    from tools.doccheck import warm as module

    def refuse(self):
        raise RuntimeError("a warm start needs Linux (pidfd_open, SOCK_SEQPACKET sockets)")

    monkeypatch.setattr(module.WarmStart, "__enter__", refuse)
    with contextlib.ExitStack() as stack:
        assert module.warm_or_cold(stack) is None
    err = capsys.readouterr().err
    assert (
        err == "note: every sdt starts fresh (a warm start needs Linux (pidfd_open, "
        "SOCK_SEQPACKET sockets))\n"
    )
