"""``sdt classifiers``: the classifiers the registry knows."""

from __future__ import annotations

import typer

from .common import print_json, registry, table

app = typer.Typer(help="List classifiers.", no_args_is_help=True)


@app.command("list")
def list_classifiers(
    ctx: typer.Context,
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
) -> None:
    """List classifiers with their estimator and hyperparameters (paper Table 3).

    Example:

      sdt classifiers list --json
    """
    specs = registry(ctx).classifiers()
    if as_json:
        print_json(
            [
                {**c.content_dict(), "plugin": c.plugin, "distribution": c.distribution}
                for c in specs
            ]
        )
        return
    rows = [
        [c.name, c.estimator, ", ".join(f"{k}={v!r}" for k, v in c.params.items()), c.distribution]
        for c in specs
    ]
    table("Classifiers", ["name", "estimator", "hyperparameters", "distribution"], rows)
