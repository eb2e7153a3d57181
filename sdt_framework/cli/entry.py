"""The ``sdt`` console script: start the command, and stop cleanly if Ctrl-C comes first.

The command's modules (numpy, pandas, scikit-learn, typer, every subcommand) take
most of a second to load. A Ctrl-C in that time used to print Python's
traceback; here it is one ``interrupted:`` line and exit status 130, as a
Ctrl-C inside a command is (:mod:`sdt_framework.cli.failures`). Only the
standard library is imported before the guard.
"""

from __future__ import annotations

import sys


def main() -> None:
    """Load the command and run it; Ctrl-C while loading exits 130 with one line."""
    try:
        from .main import main as run_sdt
    except KeyboardInterrupt:
        sys.stderr.write(
            "interrupted: stopped by Ctrl-C while sdt was starting; nothing was done.\n"
        )
        raise SystemExit(130) from None
    run_sdt()
