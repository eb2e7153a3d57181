"""A throw-away folder in which documented commands run as a user would type them.

The repository's top-level entries are linked in (so ``tests/data/endaq/...``,
``examples/...`` and ``.venv/bin/python`` resolve), HOME is the sandbox's own,
``/tmp/...`` in a command is redirected into the sandbox (and back in what it
prints), and ``sdt`` is the one installed beside the running interpreter.
"""

from __future__ import annotations

import contextlib
import os
import re
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

from .warm import WarmStart

TMP = re.compile(r"(?<![\w.~/])/tmp/")
KEEP_OUT = {".git", "results", "build"}
_LIVE: set[int] = set()  # the sessions of the commands running now (documents run side by side)
_LOCK = threading.Lock()
_STOPPED = threading.Event()


class Sandbox:
    """One document's working folder; commands run in it one after another."""

    def __init__(self, root: Path, repo: Path, cache: Path, warm: WarmStart | None = None) -> None:
        self.root, self.repo, self.cache, self.warm = root, repo, cache, warm
        (root / "home").mkdir(parents=True, exist_ok=True)
        (root / "tmp").mkdir(exist_ok=True)
        for entry in repo.iterdir():
            hidden = entry.name.startswith(".") and entry.name != ".venv"
            if not hidden and entry.name not in KEEP_OUT and not (root / entry.name).exists():
                (root / entry.name).symlink_to(entry)

    def link(self, folder: str) -> None:
        """Link every file of the repository's ``folder`` into the sandbox's top level."""
        for entry in sorted((self.repo / folder).iterdir()):
            target = self.root / entry.name
            if not target.exists():
                target.symlink_to(entry)

    def write(self, name: str, content: str) -> None:
        """A file the document shows (a ``cat FILE`` output or a ``file=`` block)."""
        path = self.root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(content, encoding="utf-8")

    def environment(self, columns: int) -> dict[str, str]:
        """The caller's environment with PATH, HOME, cache and terminal width set."""
        env = {k: v for k, v in os.environ.items() if k not in {"COLUMNS", "LINES", "SDT_DEBUG"}}
        env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env.get('PATH', '')}"
        env.update(HOME=str(self.root / "home"), SDT_CACHE_DIR=str(self.cache))
        env.update(COLUMNS=str(columns), NO_COLOR="1", TERM="dumb")
        return self.warm.environment(env) if self.warm else env

    def run(self, command: str, columns: int, timeout: float) -> tuple[int, str, float, float]:
        """Exit status, what the terminal shows (stdout and stderr), wall and CPU seconds.

        CPU seconds (the command and its workers, from ``wait4``) do not depend on
        the machine's load as wall seconds do, nor on the other documents running
        beside it, so they size the test suite's share.

        The status is the shell's ``$?``, of a pipeline's last command as a user
        sees it (``sdt ... | head -3`` is not failed by the pipe closing early);
        a crash before the pipe still shows as a traceback or missing lines.
        """
        command = TMP.sub(f"{self.root}/tmp/", command)
        env, cpu_file = self.environment(columns), None
        if self.warm:  # a warm command's CPU is the server's child's: its client writes it here
            # (in the server's folder, removed with it even if the checker stops before the unlink)
            handle, cpu_file = tempfile.mkstemp(prefix="cpu-", dir=self.warm.folder)
            os.close(handle)
            env["SDT_WARM_CPU_FILE"] = cpu_file
        start = time.monotonic()
        with _LOCK:
            if _STOPPED.is_set():
                raise KeyboardInterrupt("the checker is stopping")
            process = subprocess.Popen(
                ["bash", "-c", command],
                cwd=self.root,
                env=env,
                stdout=subprocess.PIPE,
                stderr=subprocess.STDOUT,
                start_new_session=True,
            )
            _LIVE.add(process.pid)
        expired = threading.Event()
        timer = threading.Timer(timeout, _stop, (process.pid, expired))
        timer.start()
        try:
            raw = process.stdout.read() if process.stdout else b""
            # wait4, not wait: this command's CPU (its workers' too), whatever else runs
            _, code, usage = os.wait4(process.pid, 0)
            stopped = expired.is_set()  # by the timer before it ended, not after
            process.returncode = status = os.waitstatus_to_exitcode(code)
        finally:  # the checker stopped (Ctrl-C, SIGTERM): stop the command it started
            timer.cancel()
            warm_cpu = sum(map(float, Path(cpu_file).read_text().split())) if cpu_file else 0.0
            if cpu_file:
                os.unlink(cpu_file)
            if process.returncode is None:
                _stop(process.pid, expired)
            with _LOCK:
                _LIVE.discard(process.pid)
        if stopped:
            status, raw = -1, raw + f"\n(stopped after {timeout:.0f} s)".encode()
        printed = raw.decode("utf-8", "replace")
        printed = printed.replace(f"{self.root}/tmp/", "/tmp/").replace(f"{self.root}/", "")
        return status, printed, time.monotonic() - start, usage.ru_utime + usage.ru_stime + warm_cpu


def _stop(pid: int, expired: threading.Event) -> None:
    """SIGKILL the command's whole session (its workers too), noting that it was stopped."""
    expired.set()
    with contextlib.suppress(ProcessLookupError):  # it ended meanwhile
        os.killpg(pid, signal.SIGKILL)


def stop_all() -> None:
    """Stop every running command and start no other (the checker was interrupted)."""
    with _LOCK:
        _STOPPED.set()
        for pid in _LIVE:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(pid, signal.SIGKILL)
