"""A throw-away folder in which documented commands run as a user would type them.

The repository's top-level entries are linked in (so ``tests/data/endaq/...``,
``examples/...`` and ``.venv/bin/python`` resolve), HOME is the sandbox's own,
``/tmp/...`` in a command is redirected into the sandbox (and back in what it
prints), and ``sdt`` is the one installed beside the running interpreter.
"""

from __future__ import annotations

import os
import re
import resource
import signal
import subprocess
import sys
import time
from pathlib import Path

TMP = re.compile(r"(?<![\w.~/])/tmp/")
KEEP_OUT = {".git", "results", "build"}


class Sandbox:
    """One document's working folder; commands run in it one after another."""

    def __init__(self, root: Path, repo: Path, cache: Path) -> None:
        self.root, self.repo, self.cache = root, repo, cache
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
        return env

    def run(self, command: str, columns: int, timeout: float) -> tuple[int, str, float, float]:
        """Exit status, what the terminal shows (stdout and stderr), wall and CPU seconds.

        CPU seconds (the command and its workers) do not depend on the machine's
        load as wall seconds do, so they size the test suite's share.

        The status is the shell's ``$?``, of a pipeline's last command as a user
        sees it (``sdt ... | head -3`` is not failed by the pipe closing early);
        a crash before the pipe still shows as a traceback or missing lines.
        """
        command = TMP.sub(f"{self.root}/tmp/", command)
        start, cpu = time.monotonic(), _children_cpu()
        process = subprocess.Popen(
            ["bash", "-c", command],
            cwd=self.root,
            env=self.environment(columns),
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            start_new_session=True,
        )
        try:
            raw, _ = process.communicate(timeout=timeout)
            status = process.returncode
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)  # the command's workers too
            raw, _ = process.communicate()
            status, raw = -1, raw + f"\n(stopped after {timeout:.0f} s)".encode()
        finally:  # the checker stopped (Ctrl-C, SIGTERM): stop the command it started
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGKILL)
        printed = raw.decode("utf-8", "replace")
        printed = printed.replace(f"{self.root}/tmp/", "/tmp/").replace(f"{self.root}/", "")
        return status, printed, time.monotonic() - start, _children_cpu() - cpu


def _children_cpu() -> float:
    """User and system seconds of this process's finished children so far."""
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    return used.ru_utime + used.ru_stime
