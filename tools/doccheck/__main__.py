"""``python -m tools.doccheck [--mode fast|slow|all] [--jobs N] [DOC ...]``: run, report, sum up.

Prints one line per command as it ends (PASS, FAIL with the reason and what was
printed, SKIP with the reason), the skipped list, and last ``N passed, N failed,
...``; exits 1 when a command failed. Documents are independent (one sandbox
each), so ``--jobs`` of them run side by side, the ones with the most slow
blocks first; a document's own commands always run in order.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import queue
import signal
import sys
import tempfile
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from .extract import ROOT, Command, all_steps
from .runner import Result, run_doc
from .sandbox import stop_all
from .warm import WarmStart, warm_or_cold

LABEL = {"passed": "PASS", "failed": "FAIL", "skipped": "SKIP", "xfailed": "XFAIL"}


def dump(folder: Path, command: Command, printed: str) -> None:
    """Save what a command printed, as a document would show it, to paste when it moved."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / command.dump_name).write_text(f"$ {command.text}\n{printed}", encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    """Run the selected documents' commands and print a pytest-like summary line."""
    parser = argparse.ArgumentParser(prog="python -m tools.doccheck")
    parser.add_argument("--mode", choices=["fast", "slow", "all"], default="slow")
    parser.add_argument("--dump", type=Path, help="write each command's printed output here")
    parser.add_argument("--jobs", type=int, default=2, help="documents run side by side")
    parser.add_argument(
        "--cold", action="store_true", help="every sdt in a fresh process (default: warm start)"
    )
    parser.add_argument("docs", nargs="*", help="README.md, docs/x.md (default: all)")
    args = parser.parse_args(argv)
    if args.jobs < 1:
        parser.error(f"--jobs {args.jobs}: give 1 or more documents to run side by side")
    # SIGTERM exits through the sandboxes' clean-up; the caller's handler is put back after,
    # so a test calling main() leaves its process as it found it.
    before = signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    try:
        with contextlib.ExitStack() as stack:
            folder = stack.enter_context(tempfile.TemporaryDirectory(prefix="doccheck-cache-"))
            cache = Path(os.environ.get("SDT_CACHE_DIR") or folder)  # one cache for all documents
            return check(args, cache, None if args.cold else warm_or_cold(stack))
    finally:
        signal.signal(signal.SIGTERM, before)


def check(args: argparse.Namespace, cache: Path, warm: WarmStart | None = None) -> int:
    """Run the selected documents in ``args`` with the shared ``cache``; 1 if one failed."""
    found = all_steps()
    unknown = [d for d in args.docs if d not in found]
    if unknown:
        print(f"error: no such document: {', '.join(unknown)}; give README.md or docs/NAME.md "
              f"({len(found)} documents hold commands)", file=sys.stderr)  # fmt: skip
        return 2
    selected = {d: s for d, s in found.items() if not args.docs or d in args.docs}
    counts: Counter[str] = Counter()
    skipped: list[str] = []
    start, cpu = time.monotonic(), 0.0
    for result in _run_side_by_side(selected, args.mode, cache, args.jobs, warm):
        counts[result.status] += 1
        if args.dump and result.status != "skipped":
            dump(args.dump, result.command, result.printed)
        label = LABEL.get(result.status, result.status.upper())
        cpu += result.cpu
        times = f"{result.seconds:.1f} s, CPU {result.cpu:.1f} s"
        head = f"{label:5} {result.command.id} ({times}) $ "
        print(head + result.command.text, flush=True)
        if result.status == "skipped":
            skipped.append(f"  {result.command.id}: {result.detail}")
        elif result.status in {"failed", "xfailed"}:
            print("      " + result.detail.replace("\n", "\n      "), flush=True)
    if skipped:
        print("skipped (cannot run here):\n" + "\n".join(skipped))
    order = ["passed", "failed", "skipped", "xfailed", "xpassed"]
    summary = ", ".join(f"{counts[k]} {k}" for k in order if counts[k] or k in order[:2])
    took = f"{time.monotonic() - start:.0f} s, CPU {cpu:.0f} s"
    print(f"{summary} in {took} (documented commands)")
    return 1 if counts["failed"] else 0


def _run_side_by_side(
    selected: dict, mode: str, cache: Path, jobs: int, warm: WarmStart | None = None
):
    """Yield every document's results as they come, ``jobs`` documents at a time.

    The documents with the most slow blocks start first, so the longest one
    does not start last and leave a core idle at the end.
    """
    done: queue.Queue[Result | None] = queue.Queue()

    def run(steps: list) -> None:
        try:
            for result in run_doc(steps, mode, cache, ROOT, warm):
                done.put(result)
        finally:
            done.put(None)  # this document is over

    order = sorted(selected, key=lambda d: (-sum("slow" in s.notes for s in selected[d]), d))
    pool = ThreadPoolExecutor(max_workers=jobs)
    futures = [pool.submit(run, selected[doc]) for doc in order]
    try:
        for _ in order:
            while (result := done.get()) is not None:
                yield result
        for future in futures:
            future.result()  # an error in the checker itself surfaces here
    finally:  # also on Ctrl-C or SIGTERM: stop what runs, start nothing more
        if not all(f.done() for f in futures):
            stop_all()
        pool.shutdown(wait=True, cancel_futures=True)


if __name__ == "__main__":
    sys.exit(main())
