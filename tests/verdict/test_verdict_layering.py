"""The verdict sits above bench results and below the report and the CLI."""

from __future__ import annotations

import ast
from pathlib import Path

import sdt_framework.verdict as verdict

FORBIDDEN = ("report", "cli")


def test_verdict_never_imports_the_report_or_the_cli():
    for path in sorted(Path(verdict.__file__).parent.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                names = [node.module or ""]
            elif isinstance(node, ast.Import):
                names = [alias.name for alias in node.names]
            else:
                continue
            for name in names:
                parts = name.split(".")
                top = parts[1] if parts[0] == "sdt_framework" and len(parts) > 1 else parts[0]
                assert top not in FORBIDDEN, f"{path.name} imports {name}"
