"""Documented ``sdt`` commands start from a warm process: the scientific stack is loaded once.

A fresh ``sdt`` spends 0.5-3 s importing numpy, scipy, pandas and scikit-learn
before it does anything, and the documents run a few hundred of them. The
checker starts one server (:class:`WarmStart`) that imports those libraries
and sdt's own modules and plugins (never its command line, ``sdt_framework.cli``,
which reads the environment as it loads: rich's consoles take ``COLUMNS``
then), and puts a small ``sdt`` first on the sandbox's PATH. That client hands
the server its standard streams, arguments, folder, environment and ignored
signals; the server forks a child that becomes the command: it takes them on,
starts its own session (so a timeout's kill reaches its workers too) and runs
the installed ``sdt`` console script as ``__main__``, as a fresh interpreter
would. The child's exit status and CPU
seconds go back to the client, which exits with that status. A client that
finds no server runs the installed ``sdt`` itself.

``python -m tools.doccheck --cold`` runs every command in a fresh process instead.
"""

from __future__ import annotations

import contextlib
import gc
import importlib
import importlib.metadata
import io
import json
import os
import pkgutil
import runpy
import selectors
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
from pathlib import Path

#: what ``sdt`` imports from outside itself, loaded once by the server (the slow part of a start)
PRELOAD = (
    "numpy", "scipy.signal", "scipy.stats", "scipy.ndimage", "scipy.fft", "pandas", "pyarrow",
    "pydantic", "pluggy", "typer", "rich.console", "rich.table", "rich.progress", "joblib",
    "threadpoolctl", "sklearn.ensemble", "sklearn.linear_model", "sklearn.svm",
    "sklearn.neighbors", "sklearn.neural_network", "sklearn.preprocessing",
    "sklearn.model_selection", "sklearn.metrics", "xgboost", "matplotlib", "matplotlib.figure",
    "SALib", "scikit_posthocs", "allantools", "idelib", "nptdms", "pyuff", "lvm_read", "h5py",
    "soundfile", "tomli_w",
)  # fmt: skip
#: signals a client passes on to its command; the others need no relay in a document
RELAYED = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
MAX_REQUEST = 1 << 20

#: the client, run as ``sdt`` (``-I -S``: no site, no user paths; it needs the standard library)
CLIENT = """\
#!{python} -IS
import json, os, signal, socket, sys
REAL = {real!r}
RELAYED = {relayed!r}
address = os.environ.get("SDT_WARM_SOCKET")
link = socket.socket(socket.AF_UNIX, socket.SOCK_SEQPACKET)
try:
    link.connect(address)
except (OSError, TypeError):
    os.execv(REAL, [REAL, *sys.argv[1:]])  # no server: the installed sdt, as typed
ignored = [s for s in RELAYED if signal.getsignal(s) == signal.SIG_IGN]
for number in set(RELAYED) - set(ignored):
    signal.signal(number, lambda n, _: link.send(str(n).encode()))
request = dict(argv=[REAL, *sys.argv[1:]], cwd=os.getcwd(), env=dict(os.environ), ignored=ignored)
try:
    socket.send_fds(link, [json.dumps(request).encode()], [0, 1, 2])
except OSError:  # a standard stream closed: the installed sdt copes with that itself
    os.execv(REAL, [REAL, *sys.argv[1:]])
reply = link.recv(4096)
if not reply:
    sys.exit("sdt: the warm server stopped before the command ended")
reply = json.loads(reply)
if file := os.environ.get("SDT_WARM_CPU_FILE"):
    with open(file, "a") as cpu:
        cpu.write(f"{{reply['cpu']}}\\n")
status = reply["status"]
if status < 0:  # ended by a signal: end the same way, as the shell reports it
    signal.signal(-status, signal.SIG_DFL)
    os.kill(os.getpid(), -status)
sys.exit(status)
"""


class WarmStart:
    """The server process and the folder holding the client ``sdt`` (a context manager)."""

    bin: Path  # the folder of the client ``sdt``, first on a warm command's PATH
    address: Path  # the server's socket

    def __init__(self) -> None:
        self.folder: Path | None = None  # made on entering, removed on leaving
        self.process: subprocess.Popen | None = None

    def __enter__(self) -> WarmStart:
        if not (hasattr(os, "pidfd_open") and hasattr(socket, "SOCK_SEQPACKET")):
            raise RuntimeError("a warm start needs Linux (pidfd_open, SOCK_SEQPACKET sockets)")
        self.folder = Path(tempfile.mkdtemp(prefix="doccheck-warm-"))
        self.bin, self.address = self.folder / "bin", self.folder / "server.sock"
        real = Path(sys.executable).parent / "sdt"
        self.bin.mkdir()
        client = self.bin / "sdt"
        relayed = tuple(int(number) for number in RELAYED)
        client.write_text(CLIENT.format(python=sys.executable, real=str(real), relayed=relayed))
        client.chmod(0o755)
        (self.folder / "home").mkdir()
        env = {**os.environ, "HOME": str(self.folder / "home")}  # as empty as a sandbox's
        self.process = subprocess.Popen(
            [sys.executable, "-m", "tools.doccheck.warm", str(self.address)],
            cwd=Path(__file__).resolve().parents[2],
            env=env,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            start_new_session=True,  # a Ctrl-C at the checker's terminal is the checker's
        )
        ready = self.process.stdout.readline() if self.process.stdout else b""
        if ready != b"ready\n":
            self.__exit__(None, None, None)
            raise RuntimeError("the warm sdt server did not start (its error is above)")
        return self

    def environment(self, env: dict[str, str]) -> dict[str, str]:
        """``env`` with the client first on PATH and the server's address."""
        return {**env, "PATH": f"{self.bin}{os.pathsep}{env['PATH']}",
                "SDT_WARM_SOCKET": str(self.address)}  # fmt: skip

    def __exit__(self, *exc: object) -> None:
        if self.process is not None and self.process.poll() is None:
            self.process.terminate()
            self.process.wait()
        if self.folder is not None:
            shutil.rmtree(self.folder, ignore_errors=True)
            self.folder = None


def warm_or_cold(stack: contextlib.ExitStack) -> WarmStart | None:
    """A started server, entered on ``stack``; None, with one note, where none can start
    (not Linux, or the server failed): every ``sdt`` then starts fresh."""
    try:
        return stack.enter_context(WarmStart())
    except (OSError, RuntimeError) as error:
        print(f"note: every sdt starts fresh ({error})", file=sys.stderr)
        return None


def serve(address: str) -> str | None:
    """Load the libraries (:func:`_preload`), then fork a child per request; in a child, return
    the script to run.

    One thread, one loop: a request forks at once; a child's end (its pidfd) sends the
    client the status and CPU; a client's message relays a signal; a client gone (the
    command timed out and its shell was killed) kills the child's session.
    """
    _preload()
    # what is loaded stays: a child's collector must not walk it (and copy every page it touches)
    gc.freeze()
    parent = os.getppid()
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_SEQPACKET)
    listener.bind(address)
    listener.listen(64)
    print("ready", flush=True)
    loop = selectors.DefaultSelector()
    loop.register(listener, selectors.EVENT_READ, None)
    while os.getppid() == parent:  # the checker gone (even by SIGKILL): stop
        for key, _ in loop.select(timeout=1.0):
            if key.data is None:
                script = _start(listener, loop)
                if script is not None:
                    return script
            elif key.data[0] == "ended":
                _ended(loop, *key.data[1:])
            else:
                _from_client(loop, *key.data[1:])
    return None


def _preload() -> None:
    """Import :data:`PRELOAD`, then every module of sdt but its command line, and of its
    plugins' packages.

    Every module, not the packages alone: sdt's packages load their modules on first use,
    and a child that imported (and compiled) them itself spent about 1 CPU-s of a small
    benchmark's 1.6 doing so. A module that fails to import is left out: a command that
    needs it meets the same error.
    """
    for name in PRELOAD:
        with contextlib.suppress(ImportError):  # an optional library not installed
            importlib.import_module(name)
    from sdt_framework.hookspecs import PROJECT  # here: the checker imports this module too

    plugins = {ep.module for ep in importlib.metadata.entry_points(group=PROJECT)}
    for name in ["sdt_framework", *sorted(plugins)]:
        _import_tree(name)


def _import_tree(name: str) -> None:
    """Import module ``name`` and, for a package, every module under it, but sdt's command
    line (``sdt_framework.cli``) and any ``__main__``."""
    if name in {"sdt_framework.cli", "sdt_framework.__main__"} or name.endswith(".__main__"):
        return
    try:
        module = importlib.import_module(name)
    except Exception:  # a broken module fails the command that needs it
        return
    for found in pkgutil.iter_modules(getattr(module, "__path__", []), f"{name}."):
        _import_tree(found.name)
    loaded = sorted(m for m in sys.modules if m.split(".")[:2] == ["sdt_framework", "cli"])
    if loaded:  # its consoles would keep this server's environment
        raise RuntimeError(f"the command line was loaded before any command: {loaded[:3]}")


def _start(listener: socket.socket, loop: selectors.BaseSelector) -> str | None:
    link, _ = listener.accept()
    message, fds, _, _ = socket.recv_fds(link, MAX_REQUEST, 3)
    request = json.loads(message)
    pid = os.fork()
    if pid == 0:
        listener.close()
        loop.close()
        return _become(request, fds, link)
    for fd in fds:
        os.close(fd)
    pidfd = os.pidfd_open(pid)
    loop.register(pidfd, selectors.EVENT_READ, ("ended", pid, link, pidfd))
    loop.register(link, selectors.EVENT_READ, ("client", pid, link))
    return None


def _ended(loop: selectors.BaseSelector, pid: int, link: socket.socket, pidfd: int) -> None:
    """The command ended: tell its client how, and forget both."""
    loop.unregister(pidfd)
    os.close(pidfd)
    if link in loop.get_map():  # not if the client is gone already
        loop.unregister(link)
    _, status, usage = os.wait4(pid, 0)
    reply = {"status": os.waitstatus_to_exitcode(status), "cpu": usage.ru_utime + usage.ru_stime}
    with contextlib.suppress(OSError):  # the client is gone
        link.send(json.dumps(reply).encode())
    link.close()


def _from_client(loop: selectors.BaseSelector, pid: int, link: socket.socket) -> None:
    """A signal to relay, or the client gone: then its command and workers are killed."""
    if link.fileno() == -1:  # the command ended in this same turn of the loop
        return
    try:
        message = link.recv(64)
    except OSError:
        message = b""
    with contextlib.suppress(ProcessLookupError):
        if message:
            os.kill(pid, int(message))
        else:
            loop.unregister(link)
            os.killpg(pid, signal.SIGKILL)  # the child leads its own session and group


def _become(request: dict, fds: list[int], link: socket.socket) -> str:
    """In the forked child: take on the client's streams, folder, environment and signals."""
    link.close()
    os.setsid()
    for target, fd in enumerate(fds):
        os.dup2(fd, target)
        os.close(fd)
    os.chdir(request["cwd"])
    os.environ.clear()
    os.environ.update(request["env"])
    for number in RELAYED:
        default = signal.default_int_handler if number == signal.SIGINT else signal.SIG_DFL
        signal.signal(number, signal.SIG_IGN if number in request["ignored"] else default)
    sys.stdin = sys.__stdin__ = _stream(0, "r", sys.__stdin__)
    sys.stdout = sys.__stdout__ = _stream(1, "w", sys.__stdout__)
    sys.stderr = sys.__stderr__ = _stream(2, "w", sys.__stderr__, line_buffering=True)
    sys.argv = list(request["argv"])
    sys.path[0] = str(Path(sys.argv[0]).parent)  # a script's folder, as for ``python SCRIPT``
    return sys.argv[0]


def _stream(fd: int, mode: str, like: io.TextIOWrapper, line_buffering: bool = False):
    """A standard stream on ``fd`` as the interpreter makes one at start (encoding of ``like``)."""
    raw = io.FileIO(fd, mode, closefd=False)
    buffered = io.BufferedReader(raw) if mode == "r" else io.BufferedWriter(raw)
    return io.TextIOWrapper(
        buffered,
        encoding=like.encoding,
        errors=like.errors,
        line_buffering=line_buffering or raw.isatty(),
    )


if __name__ == "__main__":
    script = serve(sys.argv[1])
    if script is not None:  # this is a command's child now: run sdt as a fresh start would
        runpy.run_path(script, run_name="__main__")
