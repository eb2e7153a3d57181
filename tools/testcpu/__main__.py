"""``python -m tools.testcpu DIR [--top N] [--tests]``: the files (or tests) that cost most CPU."""

from __future__ import annotations

import argparse
import json
import sys
from collections import defaultdict
from pathlib import Path


def read_rows(folder: Path) -> list[dict]:
    """Every test's row written under ``folder`` (one file per pytest process)."""
    rows = []
    for path in sorted(folder.glob("*.jsonl")):
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            try:
                rows.append(json.loads(line))
            except json.JSONDecodeError:
                raise ValueError(f"{path}:{number}: not a JSON line; delete the folder and "
                                 f"run the suite again") from None  # fmt: skip
    return rows


def by_file(rows: list[dict]) -> dict[str, dict[str, float]]:
    """Per test file: tests, own CPU, children's CPU and wall seconds, summed."""
    files: dict[str, dict[str, float]] = defaultdict(
        lambda: {"tests": 0, "self": 0.0, "children": 0.0, "wall": 0.0}
    )
    for row in rows:
        total = files[row["id"].split("::")[0]]
        total["tests"] += 1
        for key in ("self", "children", "wall"):
            total[key] += row[key]
    return dict(files)


def main(argv: list[str] | None = None) -> int:
    """Print the totals, then the ``--top`` files (or tests) by CPU, the costliest first."""
    parser = argparse.ArgumentParser(
        prog="python -m tools.testcpu",
        description="Sum up what `pytest -p tools.testcpu.plugin --test-cpu DIR` wrote.",
        epilog="example: python -m tools.testcpu /tmp/cpu --top 20",
    )
    parser.add_argument("folder", type=Path, help="the --test-cpu folder of a finished run")
    parser.add_argument("--top", type=int, default=25, help="how many lines (default 25)")
    parser.add_argument("--tests", action="store_true", help="single tests, not files")
    args = parser.parse_args(argv)
    if args.top < 1:
        print(f"error: --top {args.top}: give 1 or more lines", file=sys.stderr)
        return 2
    try:
        rows = read_rows(args.folder)
    except (ValueError, OSError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    if not rows:
        print(f"error: {args.folder}: no test rows; run pytest with -p tools.testcpu.plugin "
              f"--test-cpu={args.folder} first", file=sys.stderr)  # fmt: skip
        return 2
    own = sum(r["self"] for r in rows)
    children = sum(r["children"] for r in rows)
    print(f"{len(rows)} tests: CPU {own + children:.0f} s ({own:.0f} s in pytest's "
          f"processes, {children:.0f} s in their children)")  # fmt: skip
    lines = {r["id"]: {"tests": 1, **r} for r in rows} if args.tests else by_file(rows)
    ranked = sorted(lines.items(), key=lambda kv: -(kv[1]["self"] + kv[1]["children"]))
    print(f"{'CPU s':>7} {'own':>6} {'child':>6} {'wall s':>7} {'tests':>5}  file or test")
    for name, t in ranked[: args.top]:
        cpu = t["self"] + t["children"]
        print(f"{cpu:7.1f} {t['self']:6.1f} {t['children']:6.1f} {t['wall']:7.1f} "
              f"{t['tests']:5d}  {name}")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())
