"""``sdt plugins``: what is installed and whether it loaded."""

from __future__ import annotations

import typer

from .common import print_json, registry, table

app = typer.Typer(help="Inspect installed sdt-framework plugins.", no_args_is_help=True)


@app.command("list")
def list_plugins(
    ctx: typer.Context,
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
) -> None:
    """List every plugin with its distribution, version, status and what it provides.

    Status: loaded; partial (some specs it registered are invalid: not registered, one
    warning line each, the others kept); blocked; not selected; error; conflict.

    Environment switches for setups with many plugins (a name matching no installed
    plugin or distribution is a warning):

      SDT_PLUGINS=name,dist   load only these plugins (entry-point or distribution names)

      SDT_BLOCK_PLUGINS=name,dist never load these

      SDT_TRACE_HOOKS=1 print every registration to stderr

    Example:

      SDT_BLOCK_PLUGINS=sdt-adxl355 sdt plugins list --json
    """
    plugins = registry(ctx).plugins()
    if as_json:
        print_json([p.as_dict() for p in plugins])
        return
    rows = [
        [
            p.name,
            p.distribution,
            p.version,
            p.status,
            "; ".join(f"{kind}: {', '.join(names)}" for kind, names in p.provides.items()),
            p.error,
        ]
        for p in plugins
    ]
    table("Plugins", ["plugin", "distribution", "version", "status", "provides", "error"], rows)
