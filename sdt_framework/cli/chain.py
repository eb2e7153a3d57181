"""``sdt degrade`` and ``sdt validate-noise``: the measurement chain from the shell."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from ..errors import SDTError
from .common import console, print_json, print_table, registry, warn
from .guards import OVERWRITE_HELP

__all__ = ["FS_HELP", "FULL_SCALE_HELP", "SIGNAL_HELP", "degrade_command",
           "validate_noise_command"]  # fmt: skip

FS_HELP = "Rate of INPUT, Hz, for a file that holds none (NPY, CSV, MAT); checked otherwise."
SIGNAL_HELP = "Signal of a file holding several (`sdt dataset inspect FILE` lists them)."
FULL_SCALE_HELP = "Acceleration of a full-scale sample of an integer WAV file, g."


def degrade_command(
    ctx: typer.Context,
    input_path: Annotated[
        Path,
        typer.Argument(
            metavar="INPUT",
            help="Recording in any registered format (sdt plugins list; NPY, CSV, MAT, TDMS, "
            "WAV, UFF58, LVM, IDE...), in g unless the file states its units.",
        ),
    ],
    sensor: Annotated[str, typer.Option("--sensor", help="Sensor profile name, e.g. adxl345.")],
    out: Annotated[Path, typer.Option("--out", help="Output file, .npy or .csv.")],
    fs: Annotated[float | None, typer.Option("--fs", help=FS_HELP)] = None,
    signal: Annotated[str | None, typer.Option("--signal", help=SIGNAL_HELP)] = None,
    full_scale_g: Annotated[
        float | None, typer.Option("--full-scale-g", help=FULL_SCALE_HELP)
    ] = None,
    seed: Annotated[int, typer.Option("--seed", help="Base seed of the injected noise.")] = 0,
    no_noise: Annotated[bool, typer.Option("--no-noise", help="Do not inject noise.")] = False,
    first_index: Annotated[
        int, typer.Option("--first-index", help="Noise id of the first row.")
    ] = 0,
    overwrite: Annotated[bool, typer.Option("--overwrite", help=OVERWRITE_HELP)] = False,
) -> None:
    """Degrade a recording to what SENSOR would have recorded (docs/chain.md).

    INPUT is read by its registered reader, as a manifest row is: the rate and
    units from the file where it holds them (TDMS, WAV, UFF58, LVM, IDE), --fs
    where it holds none (NPY, CSV, MAT); a --fs that contradicts the file is
    refused naming both. A file holding several signals needs --signal NAME
    (`sdt dataset inspect INPUT` lists them). Each acquisition (a row of a
    2-D array; the longer axis is time) is a whole continuous acquisition; one
    acquisition is written 1-D, several as rows. A CSV's header line is skipped
    and its time column dropped (with a note). --out may not be INPUT itself,
    nor an existing file unless --overwrite is given. A file whose samples
    cannot fit in the memory available is refused before they are read.

    Example:

      sdt dataset synth --out data/synthetic --duration 2   # makes the input below

      sdt degrade data/synthetic/Vibration/Motor-2/100/healthy\\ 1/*-ch1.csv \\
        --sensor adxl345 --fs 20000 --seed 0 --out healthy_adxl345.npy

      sdt degrade tests/data/endaq/SSX_Data.IDE --signal 8:x --sensor adxl345 \\
        --out ide_adxl345.npy   # the rate from the file's timestamps
    """
    from ..chain import degrade  # scipy.signal: imported on use so `sdt --help` starts fast
    from ..signals import DEGRADE_BYTES_PER_SAMPLE
    from .guards import check_output_file, os_errors
    from .signal_io import SUFFIXES, open_input, save_array

    with os_errors():
        spec = registry(ctx).sensor(sensor)
        check_output_file(out, "--out", SUFFIXES, inputs=[input_path], overwrite=overwrite)
        split = "split it into shorter files (rows of a 2-D .npy one file at a time, with "
        opened = open_input(
            input_path, registry(ctx).signal_readers(), DEGRADE_BYTES_PER_SAMPLE,
            split + "--first-index)", signal=signal, rate_hz=fs,
            options={"full_scale_g": full_scale_g},
        )  # fmt: skip
        x = opened.read_g()
        x = x[0] if x.shape[0] == 1 else x
        y, fs_out = degrade(
            x, opened.rate_hz, spec, seed, noise=not no_noise, label=opened.label,
            first_index=first_index,
        )  # fmt: skip
        save_array(out, y)
    rows = 1 if y.ndim == 1 else y.shape[0]
    noise_state = "off" if no_noise else ("on" if spec.inject_noise else "off (profile)")
    console.print(
        f"{opened.label}: {rows} acquisition(s) x {x.shape[-1]} samples at "
        f"{opened.rate_hz:g} Hz ({opened.rate_from}) -> {rows} x {y.shape[-1]} at "
        f"{fs_out:g} Hz with {spec.name} (seed {seed}, noise {noise_state}) -> {out}",
        highlight=False,
        markup=False,  # a part's mode is in brackets
        soft_wrap=True,
    )


def _cell(stats: dict[str, Any], key: str) -> str:
    lo, hi = stats[f"{key}_ci95"]
    return f"{stats[key]:.2f} ± {stats[f'{key}_sd']:.2f} (95% CI: {lo:.2f}–{hi:.2f})"


def _p(value: float) -> str:
    return "p < 0.001" if value < 0.001 else f"p = {value:.3f}"


def _print_table(data: dict[str, Any]) -> None:
    from rich.table import Table

    has_rec = "recording" in data
    title = (
        f"Zero-motion noise, {data['sensor']}: {data['n_windows']} windows of "
        f"{data['window_length']} samples, seed {data['seed']} (paper Table 2)"
    )
    table = Table(title=title, title_justify="left")
    columns = ["Noise parameter", *(["Recording"] if has_rec else []), "SDT model"]
    columns += ["Relative error (%)", "p-value"] if has_rec else []
    for column in columns:
        table.add_column(column)
    for key, short, name in (
        ("rms_mg", "rms", "Noise RMS, mg"),
        ("nsd_ug_rthz", "nsd", "Spectral density (NSD), µg/√Hz"),
    ):
        row = [name]
        if has_rec:
            row.append(_cell(data["recording"], key))
        row.append(_cell(data["sdt"], key))
        if has_rec:
            row += [f"{data['relative_error_pct'][short]:.2f}", _p(data["p_value"][short])]
        table.add_row(*row)
    print_table(table)
    if data.get("band_note"):  # the chain passes less than 10-1500 Hz: NSD read where it passes
        band = data["band_hz"]
        warn(f"NSD read over {band[0]:g}-{band[1]:.0f} Hz: {data['band_note']}")


def validate_noise_command(
    ctx: typer.Context,
    sensor: str = typer.Option(..., "--sensor", help="Sensor profile name, e.g. adxl345."),
    axis: str = typer.Option("x", "--axis", help="Axis of the profile to check: x, y or z."),
    recording: Annotated[
        Path | None,
        typer.Option(
            "--recording",
            help="Zero-motion recording of one axis in any registered format (an enDAQ .IDE "
            "file: the --axis of the channel whose part is --sensor's, or of --channel).",
        ),
    ] = None,
    signal: Annotated[str | None, typer.Option("--signal", help=SIGNAL_HELP)] = None,
    channel: int | None = typer.Option(
        None, "--channel", help="Channel id in an .IDE recording (default: --sensor's part)."
    ),
    fs: float | None = typer.Option(
        None,
        "--fs",
        help="Rate of a recording that holds none, Hz (default: the sensor's output rate); "
        "checked against a file's own.",
    ),
    unit: str | None = typer.Option(
        None,
        "--unit",
        help="Unit of a recording that states none: g (default), mg, m/s^2 or lsb; checked "
        "against a file's own.",
    ),
    scale: float | None = typer.Option(None, "--scale", help="g per LSB when --unit lsb."),
    full_scale_g: float | None = typer.Option(None, "--full-scale-g", help=FULL_SCALE_HELP),
    seed: int = typer.Option(0, "--seed", help="Seed of the SDT noise."),
    windows: int = typer.Option(8, "--windows", help="Number of non-overlapping windows."),
    window_length: int = typer.Option(2048, "--window-length", help="Samples per window."),
    reference_fs: float = typer.Option(
        20000.0, "--reference-fs", help="Rate of the zero input fed to the chain, Hz."
    ),
    plot: Annotated[
        Path | None,
        typer.Option(
            "--plot",
            help="Save trace, ASD and Allan deviation here (.png, .pdf, .svg, ...; checked first).",
        ),
    ] = None,
    overwrite: bool = typer.Option(False, "--overwrite", help=OVERWRITE_HELP),
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
    yes: bool = typer.Option(
        False,
        "--yes",
        help="Run even when the size estimate is large or long (never one that "
        "cannot fit in memory).",
    ),
) -> None:
    """Zero-motion noise check of a sensor's chain (paper section 3.1, Table 2).

    The chain runs on x_ref = 0 at --reference-fs; its output is cut into
    --windows windows of --window-length samples; per window: RMS (mean
    removed, mg) and NSD (sqrt of the mean Welch PSD over 10..1500 Hz cut to
    the band the chain passes, said in a note when cut, µg/√Hz). With
    --recording (read by its registered reader: the rate and units from the
    file where it holds them; --fs, --unit where it does not)
    the same statistics of the recording, the relative error and Welch
    t-test p-values are added. An Allan table reads
    the white-noise density N (and VRW) and the bias instability B off the
    overlapping Allan deviation of the whole SDT output and of the whole
    recording (tau up to a twentieth of each record: more --windows reach
    longer taus), beside the values the profile configures for --axis (IEEE
    952; docs/chain.md). The size is checked first: one that cannot fit in
    memory is refused, a large or long one needs --yes; the --plot path is
    checked before the computation too.

    Example:

      sdt validate-noise --sensor adxl345 --json

      sdt validate-noise --sensor adxl357 --windows 4096 --yes --plot noise.png

      sdt validate-noise --sensor adxl345 --recording tests/data/endaq/SSX_Data.IDE --windows 4
    """
    from ..signals import Cost
    from ..validation import (  # imported on use, as in degrade
        allan_check,
        allan_seconds,
        noise_check,
        plot_formats,
        plot_noise_check,
        zero_motion_cost,
    )
    from .allan_table import print_allan_table
    from .guards import check_cost, check_output_file, os_errors
    from .signal_io import zero_motion_recording

    with os_errors():
        spec = registry(ctx).sensor(sensor)
        if axis not in ("x", "y", "z"):
            raise SDTError(f"--axis {axis!r}: use x, y or z")
        spec = spec.for_axis(axis)
        if plot is not None:
            inputs = [recording] if recording is not None else []
            formats = [f".{f}" for f in plot_formats()]
            check_output_file(plot, "--plot", formats, inputs, overwrite=overwrite)
        n_in, peak, seconds = zero_motion_cost(spec, reference_fs, windows, window_length)
        check_cost(
            f"validate-noise --windows {windows} --window-length {window_length}",
            Cost(n_in, peak, seconds + allan_seconds(windows * window_length)),
            yes,
            "--windows or --window-length",
        )
        rec = None
        if recording is not None:
            rec, fs = zero_motion_recording(
                registry(ctx).signal_readers(), recording, spec, axis, channel=channel,
                signal=signal, fs=fs, unit=unit, scale=scale, full_scale_g=full_scale_g,
                reference_fs=reference_fs,
            )  # fmt: skip
        result = noise_check(
            spec,
            recording=rec,
            recording_fs=fs,
            seed=seed,
            fs_ref=reference_fs,
            n_windows=windows,
            window_length=window_length,
            label=str(recording or ""),
        )
        allan = allan_check(result, spec)
        if plot is not None:
            plot_noise_check(result, plot, allan)
    data = {**result.to_dict(), "axis": axis, "allan": allan.to_dict()}
    if as_json:
        print_json(data)
        return
    _print_table(data)
    print_allan_table(data["allan"], result.sensor, axis)
    if plot is not None:
        console.print(f"figure: {plot}", highlight=False)
