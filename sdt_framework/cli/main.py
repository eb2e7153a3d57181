"""Entry point of the ``sdt`` command: the root app and user-error handling.

Every command is registered one way: a command is a function in
:data:`COMMANDS`, a group of subcommands is a Typer app in :data:`GROUPS`,
each under the name the user types; adding one is adding its line here.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from pathlib import Path

import click
import typer
import typer.main

from . import classifiers, features, plugins, sensors, twin
from . import dataset as dataset_cli
from .benchmark import benchmark
from .budget import budget
from .chain import degrade_command, validate_noise_command
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
#: command name -> the function it runs, in the order ``sdt --help`` lists them
COMMANDS: dict[str, Callable[..., None]] = {
    "degrade": degrade_command,
    "validate-noise": validate_noise_command,
    "benchmark": benchmark,
    "report": report,
    "explore": explore,
    "budget": budget,
    "compare": compare,
}
#: group name -> its Typer app of subcommands (``sdt sensors list``)
GROUPS: dict[str, typer.Typer] = {
    "plugins": plugins.app,
    "sensors": sensors.app,
    "features": features.app,
    "classifiers": classifiers.app,
    "dataset": dataset_cli.app,
    "twin": twin.app,
}
for _name, _function in COMMANDS.items():
    app.command(_name)(_function)
for _name, _group in GROUPS.items():
    app.add_typer(_group, name=_name)


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

    A problem with the input or the environment prints one line and exits with status 2;
    a bug in sdt prints one 'internal error:' line and exits with 70 (SDT_DEBUG=1 shows the
    traceback of any error); Ctrl-C exits with 130.

    Example:

      sdt sensors list

      sdt twin fit tests/data/endaq/SSX_Data.IDE --sensor adxl345 --out adxl345-fitted.toml

      sdt --sensor-file adxl345-fitted.toml sensors show adxl345-fitted
    """
    ctx.ensure_object(dict)
    ctx.obj["sensor_files"] = sensor_file


@functools.cache
def command() -> click.Command:
    """The click command Typer builds from :data:`app`, built once per process.

    ``app()`` builds it again at every call (about 20 ms: every option of every
    command read from its function's signature); a process that runs several
    commands (a notebook, the test suite) pays it once.
    """
    return typer.main.get_command(app)


def main() -> None:
    """Run ``sdt``; a user or environment error prints one line and exits with status 2,
    a bug with 70, Ctrl-C with 130 (see :mod:`sdt_framework.cli.failures`)."""
    run(command())
