"""``sdt features``: feature sets and their edge payload."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated

import typer

from ..errors import SDTError
from .chain import FS_HELP, FULL_SCALE_HELP, SIGNAL_HELP
from .common import console, print_json, registry, table
from .features_speed import SPEED_HELP, extract_context
from .guards import OVERWRITE_HELP

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


@app.command("extract")
def extract_features(
    ctx: typer.Context,
    input_path: Annotated[
        Path,
        typer.Argument(
            metavar="INPUT",
            help="Signal in any registered format (NPY, CSV, MAT, TDMS, WAV, UFF58, LVM, "
            "IDE...), in g unless the file states its units.",
        ),
    ],
    out: Annotated[
        Path, typer.Option("--out", help="Output .csv or .parquet (written atomically).")
    ],
    fs: Annotated[float | None, typer.Option("--fs", help=FS_HELP)] = None,
    signal: Annotated[str | None, typer.Option("--signal", help=SIGNAL_HELP)] = None,
    full_scale_g: Annotated[
        float | None, typer.Option("--full-scale-g", help=FULL_SCALE_HELP)
    ] = None,
    feature_set: Annotated[
        str,
        typer.Option("--set", help="Feature set name, or names joined by '+' (paper8+env_bpfo)."),
    ] = "paper8",
    window_s: Annotated[float, typer.Option("--window-s", help="Window length T_w, s.")] = 0.64,
    settle_s: Annotated[
        float, typer.Option("--settle-s", help="Settling discard per acquisition, s.")
    ] = 0.1,
    overwrite: Annotated[bool, typer.Option("--overwrite", help=OVERWRITE_HELP)] = False,
    speed_rpm: Annotated[
        float | None, typer.Option("--speed-rpm", help=SPEED_HELP["speed"])
    ] = None,
    nominal_rpm: Annotated[
        float | None, typer.Option("--nominal-rpm", help=SPEED_HELP["nominal"])
    ] = None,
    machines: Annotated[
        Path | None, typer.Option("--machines", help=SPEED_HELP["machines"])
    ] = None,
    machine: Annotated[str | None, typer.Option("--machine", help=SPEED_HELP["machine"])] = None,
    channel: Annotated[str | None, typer.Option("--channel", help=SPEED_HELP["channel"])] = None,
) -> None:
    """Extract features: one row per window, with acquisition and window index.

    INPUT is read by its registered reader, as `sdt degrade` reads it: the
    rate and units from the file where it holds them, --fs where it holds
    none (a --fs that contradicts the file is refused naming both), --signal
    NAME where it holds several; each acquisition is a row of a 2-D array
    (the longer axis is time). Units travel with the values: a CSV feature
    column is headed 'name\\[unit]' (V_RMS\\[mm/s]); a Parquet feature column
    carries 'unit' field metadata.
    --out may not be INPUT (nor a link to it), nor an existing file unless
    --overwrite is given; its folder is checked first. A
    file whose samples (from its header) cannot fit in the memory available is
    refused before it is read.

    Example:

      sdt dataset synth --out data/synthetic --duration 2   # makes the next line's input

      sdt degrade data/synthetic/Vibration/Motor-2/100/healthy\\ 1/*-ch1.csv \\
        --sensor adxl345 --fs 20000 --out healthy_adxl345.npy

      sdt features extract healthy_adxl345.npy --fs 3200 --set paper8 --out features.parquet

      sdt features extract tests/data/endaq/SSX_Data.IDE --signal 8:x --out ide_features.csv

      sdt features extract healthy_adxl345.npy --fs 3200 --set orders --speed-rpm 1480 \\
        --out orders.csv   # in orders of the running speed; --nominal-rpm 1480 estimates it
    """
    from ..features import extract, resolve_feature_set, write_feature_table
    from ..signals import FEATURES_BYTES_PER_SAMPLE
    from .guards import check_output_file, os_errors
    from .signal_io import open_input

    for option, seconds in (("--window-s", window_s), ("--settle-s", settle_s)):
        if not math.isfinite(seconds):
            raise SDTError(f"{option} {seconds}: give a finite number of seconds")
    spec = resolve_feature_set(registry(ctx), feature_set)
    if out.suffix.lower() not in {".csv", ".parquet"}:
        raise SDTError(f"{out}: --out must end in .csv or .parquet")
    with os_errors():
        check_output_file(
            out, "--out", (".csv", ".parquet"), inputs=[input_path], overwrite=overwrite
        )
        advice = "split it into shorter files (rows of a 2-D .npy a few at a time)"
        opened = open_input(
            input_path, registry(ctx).signal_readers(), FEATURES_BYTES_PER_SAMPLE, advice,
            signal=signal, rate_hz=fs, options={"full_scale_g": full_scale_g},
        )  # fmt: skip
        samples = opened.read_g()
        context = extract_context(
            spec, samples, opened.rate_hz, opened.label, speed_rpm=speed_rpm,
            nominal_rpm=nominal_rpm, machines=machines, machine_name=machine, channel=channel,
        )  # fmt: skip
        result = extract(
            samples, opened.rate_hz, spec, window_s=window_s, settle_s=settle_s,
            label=opened.label, context=context,
        )  # fmt: skip
        write_feature_table(result, out)
    n_acq = len(set(result.acquisition.tolist()))
    console.print(
        f"{opened.label} at {opened.rate_hz:g} Hz ({opened.rate_from}): wrote "
        f"{result.values.shape[0]} windows x {len(result.names)} features "
        f"({spec.name}, {result.window_length} samples/window, {n_acq} acquisition(s), "
        f"{spec.bytes_per_window} B/window/axis) to {out}",
        markup=False,
        highlight=False,
        soft_wrap=True,
    )
    if result.speed:
        console.print(f"speed: {result.speed}", markup=False, highlight=False, soft_wrap=True)
