"""A test campaign's folder of NI TDMS files, written from the synthetic pump.

What a campaign logged with an NI 9234 (IEPE, 25.6 kHz) leaves on disk: one
TDMS file per run, ``OUT/<machine>/<condition> <severity>/run<N>.tdms``, where
a healthy folder carries no severity (``healthy/run1.tdms`` beside
``impeller 2/run1.tdms``). Each file holds the accelerometer channel in g
(group ``Vibration``, the synthetic pump's ch1 resampled from 20 kHz to
25.6 kHz) beside what a logger records with it (group ``Process``): a bearing
temperature in degC and a once-per-revolution tachometer in V. These two are
stand-ins (a constant 41 degC at 100 Hz, a 5 V pulse at 24.5 Hz), not generated signals:
they are there because real files carry such channels, and the manifest must
leave them out. Used by README.md ("Your own data") and the `sdt dataset
manifest --help` examples::

    python examples/daq_campaign.py campaign
    sdt dataset manifest campaign --pattern '{machine}/{condition} {severity?}/{run}.tdms' \\
        --out campaign.csv
    sdt benchmark --quick --data campaign.csv

An OUT that exists is refused, so nothing is overwritten.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
from nptdms import ChannelObject, TdmsWriter
from scipy.signal import resample_poly
from sdt_plugins.datasets.synthetic_pump import open_synthetic

DAQ_RATE_HZ = 25600.0  # an NI 9234's default: 51.2 kHz / 2
UP, DOWN = 32, 25  # 20 kHz * 32 / 25 = 25.6 kHz
TEMPERATURE_RATE_HZ = 100.0


def _process_channels(n: int, seconds: float) -> list[ChannelObject]:
    """The logger's other channels: a bearing temperature and a tachometer (stand-ins)."""
    temperature = np.full(max(1, round(seconds * TEMPERATURE_RATE_HZ)), 41.0)
    t = np.arange(n) / DAQ_RATE_HZ
    tacho = np.where((t * 24.5) % 1.0 < 0.1, 5.0, 0.0)
    return [
        ChannelObject("Process", "Bearing temperature", temperature, properties={
            "wf_increment": 1 / TEMPERATURE_RATE_HZ, "unit_string": "degC"}),
        ChannelObject("Process", "Tacho", tacho, properties={
            "wf_increment": 1 / DAQ_RATE_HZ, "unit_string": "V"}),
    ]  # fmt: skip


def write_campaign(out: Path, duration: float, machine: str = "Motor-2") -> int:
    """Write the campaign under ``out`` (which must not exist); the number of files."""
    out.mkdir(parents=True)
    runs: dict[str, int] = {}
    dataset = open_synthetic(machines=machine, channels="ch1", duration=duration)
    for rec, data in dataset.iter_loaded():
        folder = rec.condition if rec.severity is None else f"{rec.condition} {rec.severity}"
        runs[folder] = runs.get(folder, 0) + 1
        file = out / rec.machine / folder / f"run{runs[folder]}.tdms"
        file.parent.mkdir(parents=True, exist_ok=True)
        acc = resample_poly(data[0], UP, DOWN)
        props = {"wf_increment": 1 / DAQ_RATE_HZ, "unit_string": "g"}
        with TdmsWriter(file) as writer:
            writer.write_segment(
                [ChannelObject("Vibration", rec.channel, acc, properties=props),
                 *_process_channels(len(acc), duration)]
            )  # fmt: skip
    return sum(runs.values())


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path, help="folder to create")
    parser.add_argument("--duration", type=float, default=4.0, help="seconds per run")
    args = parser.parse_args(argv)
    if args.out.exists():
        print(f"error: {args.out} exists; name a new folder", file=sys.stderr)
        return 2
    if not 0.2 < args.duration < 3600:
        print(f"error: --duration {args.duration:g}: give seconds above 0.2", file=sys.stderr)
        return 2
    count = write_campaign(args.out, args.duration)
    print(f"wrote {count} TDMS files under {args.out}/")
    return 0


if __name__ == "__main__":
    sys.exit(main())
