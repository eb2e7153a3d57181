"""The pytest side of :mod:`tools.testcpu`: one JSON line per test, per pytest process."""

from __future__ import annotations

import json
import resource
import time
from pathlib import Path

import pytest


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(
        "--test-cpu",
        metavar="DIR",
        type=Path,
        help="write each test's CPU (own and children's) and wall seconds to DIR/<worker>.jsonl",
    )


def pytest_configure(config: pytest.Config) -> None:
    """Refuse a folder that holds an earlier run's rows: this run's would be added to them."""
    folder = config.getoption("--test-cpu")
    if folder is None or hasattr(config, "workerinput"):  # checked once, in the main process
        return
    if any(Path(folder).glob("*.jsonl")):
        raise pytest.UsageError(
            f"--test-cpu {folder}: holds an earlier run's rows, which this run's would be "
            "added to; give a new folder (as --test-cpu=DIR: an existing folder given after "
            "a space is also taken for a test path)"
        )


def _cpu() -> tuple[float, float]:
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime, children.ru_utime + children.ru_stime


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item: pytest.Item, nextitem: pytest.Item | None):
    folder = item.config.getoption("--test-cpu")
    if folder is None:
        yield
        return
    own, children, start = *_cpu(), time.monotonic()
    yield
    own_after, children_after = _cpu()
    row = {
        "id": item.nodeid,
        "self": round(own_after - own, 3),
        "children": round(children_after - children, 3),
        "wall": round(time.monotonic() - start, 3),
    }
    folder.mkdir(parents=True, exist_ok=True)
    # a pytest-xdist worker's id (not PYTEST_XDIST_WORKER: a pytest started by a test inherits it)
    worker = getattr(item.config, "workerinput", {}).get("workerid", "main")
    with open(folder / f"{worker}.jsonl", "a", encoding="utf-8") as handle:
        handle.write(json.dumps(row) + "\n")
