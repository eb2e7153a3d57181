"""Entry point of the ``sdt`` command: the root app and user-error handling."""

from __future__ import annotations

from pathlib import Path

import typer

from . import classifiers, features, plugins, sensors, twin
from . import dataset as dataset_cli
from .benchmark import benchmark
from .budget import budget
from .chain import register as register_chain_commands
from .compare import compare
from .explore import explore
from .failures import InterruptibleGroup, run
from .report import report

app = typer.Typer(
    name="sdt",
    help="Sensor Digital Twin: benchmark accelerometers for vibration diagnostics on a laptop.",
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    rich_markup_mode="rich",
    cls=InterruptibleGroup,
)
app.add_typer(plugins.app, name="plugins")
app.add_typer(sensors.app, name="sensors")
app.add_typer(features.app, name="features")
app.add_typer(classifiers.app, name="classifiers")
app.add_typer(dataset_cli.app, name="dataset")
app.add_typer(twin.app, name="twin")
register_chain_commands(app)
app.command("benchmark")(benchmark)
app.command("report")(report)
app.command("explore")(explore)
app.command("budget")(budget)
app.command("compare")(compare)


@app.callback()
def root(
    ctx: typer.Context,
    sensor_file: list[Path] = typer.Option(
        [],
        "--sensor-file",
        help="A TOML sensor profile to add (repeatable). SDT_SENSOR_PATH adds folders of them.",
    ),
) -> None:
    """Sensor Digital Twin: benchmark accelerometers for vibration diagnostics on a laptop.

    A problem with the input or the environment prints one line and exits with status 2
    (SDT_DEBUG=1 shows the traceback of an operating-system error); Ctrl-C exits with 130.

    Example:

      sdt sensors list

      sdt --sensor-file my_sensor.toml sensors show my-sensor
    """
    ctx.ensure_object(dict)
    ctx.obj["sensor_files"] = sensor_file


def main() -> None:
    """Run ``sdt``; a user or environment error prints one line and exits with status 2,
    Ctrl-C exits with 130 (see :mod:`sdt_framework.cli.failures`)."""
    run(app)
