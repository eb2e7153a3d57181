"""``python -m sdt_framework`` runs the ``sdt`` command."""

from __future__ import annotations

from .cli.entry import main

main()
