"""``sdt dataset``: list datasets, write the synthetic one to disk, inspect any of them."""

from __future__ import annotations

import math
import time
from pathlib import Path
from typing import Annotated, Any

import typer

from ..errors import SDTError
from .common import err_console, print_json, registry, shorten_labels, table
from .dataset_files import inspect_file, is_manifest_csv, manifest
from .dataset_inspect import open_inspected, print_dataset

MANIFESTS = (".csv", ".parquet", ".toml")

app = typer.Typer(help="List, generate and inspect datasets.", no_args_is_help=True)


@app.command("list")
def list_datasets(
    ctx: typer.Context,
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
) -> None:
    """List registered datasets and whether they need a path.

    Example:

      sdt dataset list --json
    """
    specs = registry(ctx).datasets()
    if as_json:
        print_json(
            [
                {**d.content_dict(), "plugin": d.plugin, "distribution": d.distribution}
                for d in specs
            ]
        )
        return
    rows = [
        [d.name, "yes" if d.requires_path else "no", d.description, d.distribution] for d in specs
    ]
    table("Datasets", ["name", "needs path", "description", "distribution"], rows)


@app.command("synth")
def synth(
    ctx: typer.Context,
    out: Annotated[Path, typer.Option("--out", help="Folder to write Vibration/... into.")],
    seed: int | None = typer.Option(None, "--seed", help="Base seed (default 0)."),
    acquisitions: int | None = typer.Option(
        None, "--acquisitions", help="Acquisitions (CSV columns) per file (default 1)."
    ),
    duration: float | None = typer.Option(
        None, "--duration", help="Seconds per acquisition (default 12)."
    ),
    speeds: str | None = typer.Option(
        None,
        "--speeds",
        help="Speeds, % of rated, comma-separated (Motor-2: 50, 75, 100; Motor-4: 70), each in "
        "Vibration/<machine>/<speed>/. Default: the paper's (Motor-4 70, Motor-2 100).",
    ),
    overwrite: bool = typer.Option(
        False,
        "--overwrite",
        help="Write into an --out that already holds recordings, replacing files of the same "
        "name (other files are left and counted).",
    ),
    yes: bool = typer.Option(
        False,
        "--yes",
        help="Run even when the size estimate is large or long (never one that "
        "cannot fit in memory or on disk).",
    ),
) -> None:
    """Write the synthetic pump dataset in the NLN-EMP layout and CSV format.

    The result reads back with the NLN-EMP reader (``sdt dataset inspect OUT``).
    An --out that already holds recordings (files under OUT/Vibration) is
    refused unless --overwrite is given. The size (samples, memory, disk, time)
    is estimated first: a size that cannot fit is refused, a large or long one
    needs --yes.

    Example:

      sdt dataset synth --out data/synthetic --seed 1 --acquisitions 5 --duration 12

      sdt dataset synth --out data/synthetic --duration 2 --overwrite

      sdt dataset synth --out data/speeds --speeds 50,75,100 --duration 2
    """
    from ..data import open_dataset, synth_cost, write_nln_emp  # heavy (scipy, pyarrow)
    from .guards import check_cost, check_output_folder, os_errors

    if duration is not None and not (math.isfinite(duration) and duration > 0.2):
        raise SDTError(f"--duration {duration}: give a finite number of seconds above 0.2")
    with os_errors(str(out)):
        existing = _existing_recordings(out, overwrite)
        given = {"seed": seed, "acquisitions": acquisitions, "duration": duration, "speeds": speeds}
        options = {key: value for key, value in given.items() if value is not None}
        dataset = open_dataset(registry(ctx), "synthetic-pump", **options)
        recordings = dataset.recordings()
        cost = synth_cost(
            len(recordings),
            len(dataset.channels),
            dataset.acquisitions,
            dataset.duration,
            recordings[0].sampling_rate_hz,  # the generator's rate, as its recordings give it
            dataset.kept_at_most(sum(r.total_samples for r in recordings)),
        )
        check_output_folder(out, "--out")
        check_cost("dataset synth", cost, yes, "--duration or --acquisitions", folder=out)
        start = time.perf_counter()
        written = write_nln_emp(dataset, out)
        size = sum(p.stat().st_size for p in written) / 1e6
    err_console.print(
        f"wrote {len(written)} files ({size:.1f} MB) under {out / 'Vibration'} "
        f"in {time.perf_counter() - start:.1f} s",
        highlight=False,
    )
    others = existing - {p.resolve() for p in written}
    if others:
        err_console.print(
            f"note: {len(others)} other file(s) under {out / 'Vibration'} were not written by "
            f"this run and were left as they were",
            markup=False,
            highlight=False,
            soft_wrap=True,
        )


def _existing_recordings(out: Path, overwrite: bool) -> set[Path]:
    """Files already under OUT/Vibration; refused unless ``overwrite``."""

    if out.exists() and not out.is_dir():
        raise SDTError(f"--out {out} is a file; give a folder (new, or empty of recordings)")
    root = out / "Vibration"
    existing = {p.resolve() for p in root.rglob("*") if p.is_file()} if root.is_dir() else set()
    if existing and not overwrite:
        raise SDTError(
            f"--out {out} already holds recordings ({len(existing)} files under {root}); "
            f"choose a new folder, or pass --overwrite to replace files of the same name"
        )
    return existing


@app.command("inspect")
def inspect(
    ctx: typer.Context,
    path_or_name: str = typer.Argument(
        ...,
        help="NLN-EMP folder, manifest .csv/.parquet, a dataset name, or one signal file "
        "(TDMS, UFF58, WAV, LVM, MAT, NPY, IDE...).",
    ),
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
    validate: bool = typer.Option(
        False, "--validate", help="Parse every file now (fills the cache; finds bad rows)."
    ),
    speeds: str | None = typer.Option(
        None,
        "--speeds",
        help="Speed folders to read: 'all' or e.g. 50,75,100 (default: the dataset's own "
        "choice, for NLN-EMP the paper's speeds).",
    ),
    estimate_speed: bool = typer.Option(
        False,
        "--estimate-speed",
        help="Read the speed of each recording that carries none off its spectrum (the 1x "
        "line near the nominal speed, mains lines skipped): named an estimate, with its "
        "confidence. Reads those files.",
    ),
    nominal_rpm: float | None = typer.Option(
        None,
        "--nominal-rpm",
        help="The speed to look near, rpm (default: the machine's, machines.toml); implies "
        "--estimate-speed.",
    ),
) -> None:
    """Summarise a dataset: one line per recording, then what was skipped and why.

    An enDAQ .IDE recording lists its channels instead: subchannels (axes),
    units, the sensor table's parts and the rate measured from the timestamps.
    Any other signal file lists its signals: the manifest 'variable' naming
    each, rate and units from the file. A .csv is a manifest when its first
    line names manifest columns (path, condition...), else a signal file.

    Example:

      sdt dataset inspect tests/data/endaq/SSX66115.IDE

      sdt dataset inspect tests/data/readers/raw1.tdms

      sdt dataset synth --out data/synthetic --duration 2   # an NLN-EMP-shaped folder

      sdt dataset inspect data/synthetic --validate

      sdt dataset inspect synthetic-pump

      sdt dataset inspect data/synthetic --speeds all

      sdt dataset inspect synthetic-pump --estimate-speed   # its machines give the nominal speed
    """
    from ..signals import channel_reader

    recorder = channel_reader(path_or_name, registry(ctx).signal_readers())
    if recorder is not None:  # a file of channels (IDE)
        _inspect_channels(recorder, path_or_name, as_json)
        return
    if _is_signal_file(path_or_name):
        inspect_file(ctx, path_or_name, as_json)
        return
    if Path(path_or_name).suffix.lower() == ".toml":
        raise SDTError(
            f"{path_or_name}: a .toml file is not a dataset; a pair file (a reference and a "
            f"device) is read by `sdt twin check {path_or_name} --sensor NAME`; a dataset is a "
            f"folder, a manifest .csv/.parquet, an .IDE file or a registered name"
        )

    dataset = open_inspected(ctx, path_or_name, speeds=speeds, validate=validate,
                             estimate=estimate_speed, nominal_rpm=nominal_rpm)  # fmt: skip
    info = dataset.describe()
    for note in dataset.notes:
        err_console.print(f"note: {shorten_labels(note)}", markup=False, highlight=False,
                          soft_wrap=True)  # fmt: skip
    if as_json:
        print_json(info)
        return
    print_dataset(info, dataset.summary_line())


def _is_signal_file(path: str) -> bool:
    """A file (not a folder, not a manifest or pair file) given to ``inspect``; a .csv whose
    first line names no manifest column is a signal file."""
    candidate = Path(path).expanduser()
    if not candidate.is_file():
        return False
    if candidate.suffix.lower() == ".csv":
        return not is_manifest_csv(candidate)
    return candidate.suffix.lower() not in MANIFESTS


app.command("manifest")(manifest)


def _inspect_channels(reader: Any, path: str, as_json: bool) -> None:
    """Channels of a recorder file (IDE): parts, axes, units, samples, measured and median
    rates."""
    from .guards import os_errors

    with os_errors(path):
        channels, notes = reader.channels(path)
    for note in notes:
        err_console.print(f"note: {note}", markup=False, highlight=False, soft_wrap=True)
    for channel in channels:  # shown, and refused when the channel is read
        if channel.time_fault:
            err_console.print(f"warning: {channel.time_fault}", markup=False, highlight=False,
                              soft_wrap=True)  # fmt: skip
    if as_json:
        print_json([c.as_dict() for c in channels])
        return
    rows = [
        [c.id, c.name, ", ".join(c.parts) or "-",
         ", ".join(f"{s.axis or s.name} [{s.units}]" for s in c.subchannels), c.samples,
         f"{c.start_s:.3f}-{c.end_s:.3f}", f"{c.rate_hz:.2f}", f"{c.median_rate_hz:.2f}"]
        for c in channels
    ]  # fmt: skip
    table(
        f"{path}: {len(channels)} channels (rates from timestamps)",
        ["channel", "name", "parts", "subchannels", "samples", "time s", "rate Hz",
         "median Hz"],
        rows,
    )  # fmt: skip
