"""``sdt features``: feature sets and their edge payload."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any

import typer

from ..errors import SDTError
from .common import console, print_json, registry, table
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


def _load_npy(path: Path) -> Any:
    """Read a .npy signal; numpy is imported here to keep ``sdt --help`` fast."""
    import numpy as np

    from ..data.tokens import brief

    if path.suffix.lower() != ".npy":
        raise SDTError(f"{path}: input must be a .npy file (1-D, or 2-D rows = acquisitions)")
    from ..inputs import require_regular_file

    require_regular_file(path, "signal file")
    if not path.is_file():
        what = "is a folder; give the signal file" if path.is_dir() else "no such file"
        raise SDTError(f"{path}: {what}; check the path")
    try:
        return np.load(path, allow_pickle=False)
    except (OSError, ValueError, EOFError) as exc:
        raise SDTError(f"{path}: cannot read as .npy ({brief(exc)})") from None


@app.command("extract")
def extract_features(
    ctx: typer.Context,
    input_path: Annotated[
        Path,
        typer.Argument(
            metavar="INPUT", help="Signal in g: .npy, 1-D or 2-D (rows = acquisitions)."
        ),
    ],
    fs: Annotated[float, typer.Option("--fs", help="Sampling rate of INPUT, Hz.")],
    out: Annotated[
        Path, typer.Option("--out", help="Output .csv or .parquet (written atomically).")
    ],
    feature_set: Annotated[
        str,
        typer.Option("--set", help="Feature set name, or names joined by '+' (paper8+env_bpfo)."),
    ] = "paper8",
    window_s: Annotated[float, typer.Option("--window-s", help="Window length T_w, s.")] = 0.64,
    settle_s: Annotated[
        float, typer.Option("--settle-s", help="Settling discard per acquisition, s.")
    ] = 0.1,
    overwrite: Annotated[bool, typer.Option("--overwrite", help=OVERWRITE_HELP)] = False,
) -> None:
    """Extract features: one row per window, with acquisition and window index.

    Units travel with the values: a CSV feature column is headed 'name\\[unit]'
    (V_RMS\\[mm/s]); a Parquet feature column carries 'unit' field metadata.
    --out may not be INPUT (nor a link to it), nor an existing file unless
    --overwrite is given; its folder is checked first. A
    file whose samples (from its header) cannot fit in the memory available is
    refused before it is read.

    Example:

      sdt dataset synth --out data/synthetic --duration 2   # makes the next line's input

      sdt degrade data/synthetic/Vibration/Motor-2/100/healthy\\ 1/*-ch1.csv \\
        --sensor adxl345 --fs 20000 --out healthy_adxl345.npy

      sdt features extract healthy_adxl345.npy --fs 3200 --set paper8 --out features.parquet
    """
    from ..data.signal_sizes import FEATURES_BYTES_PER_SAMPLE
    from ..features import extract, resolve_feature_set, write_feature_table
    from .guards import check_output_file, os_errors
    from .signal_io import check_signal_size

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
        if input_path.suffix.lower() == ".npy":
            check_signal_size(input_path, FEATURES_BYTES_PER_SAMPLE, advice)
        signal = _load_npy(input_path)
        result = extract(
            signal, fs, spec, window_s=window_s, settle_s=settle_s, label=str(input_path)
        )
        write_feature_table(result, out)
    n_acq = len(set(result.acquisition.tolist()))
    console.print(
        f"wrote {result.values.shape[0]} windows x {len(result.names)} features "
        f"({spec.name}, {result.window_length} samples/window, {n_acq} acquisition(s), "
        f"{spec.bytes_per_window} B/window/axis) to {out}",
        markup=False,
        highlight=False,
        soft_wrap=True,
    )
