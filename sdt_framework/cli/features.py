"""``sdt features``: feature sets and their edge payload."""

from __future__ import annotations

import typer

from .common import print_json, registry, table

app = typer.Typer(help="List feature sets and extract features.", no_args_is_help=True)


@app.command("list")
def list_features(
    ctx: typer.Context,
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
) -> None:
    """List feature sets with their features, units and bytes per window per axis.

    Example:

      sdt features list --json
    """
    sets = registry(ctx).feature_sets()
    if as_json:
        print_json(
            [
                {
                    **s.content_dict(),
                    "plugin": s.plugin,
                    "distribution": s.distribution,
                    "bytes_per_window_per_axis": s.bytes_per_window,
                    "bytes_per_window_triaxial": 3 * s.bytes_per_window,
                }
                for s in sets
            ]
        )
        return
    rows = [
        [
            s.name,
            ", ".join(f"{n} [{u}]" for n, u in zip(s.feature_names, s.units, strict=True)),
            s.bytes_per_window,
            3 * s.bytes_per_window,
            s.distribution,
        ]
        for s in sets
    ]
    table("Feature sets", ["name", "features [unit]", "B/axis", "B/triaxial", "distribution"], rows)
