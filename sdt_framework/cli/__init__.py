"""The ``sdt`` command-line interface (typer + rich)."""
