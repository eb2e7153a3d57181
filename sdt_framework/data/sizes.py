"""What writing the synthetic pump costs, known before anything is generated.

``sdt dataset synth --duration`` estimates its peak memory, disk output and
run time from the sizes alone (the machine's side and the policy are in
:mod:`sdt_framework.signals.sizes` and ``sdt_framework.cli.guards``). The
factors below were measured, not guessed:

- Synthetic pump, one run (5 channels): peak traced memory 5.8-6.6 x the
  run's float64 samples (``tracemalloc`` over ``generate_run``, every class,
  2 s and 8 s acquisitions); writing adds the CSV table of one file.
- Writing the NLN-EMP CSVs: 17.7 bytes per sample with 1 acquisition per file
  (92.1 MB for 260 files x 20 000 samples), of which ~8 for the time column;
  1.8 M samples/s generated and written (``sdt dataset synth --duration 1``,
  2.9 s, 2 shared cores).
"""

from __future__ import annotations

from ..signals.sizes import Cost

__all__ = ["SYNTH_SAMPLES_PER_S", "synth_cost"]

#: peak bytes per float64 sample of one generated run (measured 6.6 x 8, rounded up)
SYNTH_RUN_BYTES_PER_SAMPLE = 8 * 8
#: CSV bytes per sample of an acquisition column, and per row for the time column
CSV_BYTES_PER_VALUE = 10
CSV_BYTES_PER_ROW = 8
#: generated-and-written samples per second (measured 1.8 M/s, rounded down)
SYNTH_SAMPLES_PER_S = 1.5e6


def synth_cost(
    n_recordings: int,
    channels: int,
    acquisitions: int,
    duration_s: float,
    fs_hz: float,
    kept_bytes: int = 0,
) -> Cost:
    """Cost of writing ``n_recordings`` synthetic recordings as NLN-EMP CSVs.

    Memory is the peak of one run (``channels`` recordings generated together) plus
    the runs the dataset keeps for the next read (``kept_bytes``: ``Dataset.kept_at_most``);
    disk is every CSV; time is every sample generated and written.
    """
    rows = round(duration_s * fs_hz)
    per_recording = rows * acquisitions
    samples = n_recordings * per_recording
    memory = channels * per_recording * SYNTH_RUN_BYTES_PER_SAMPLE + kept_bytes
    disk = n_recordings * rows * (CSV_BYTES_PER_ROW + CSV_BYTES_PER_VALUE * acquisitions)
    return Cost(samples, memory, samples / SYNTH_SAMPLES_PER_S, disk)
