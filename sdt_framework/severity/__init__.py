"""ISO severity zones and alarms: what a vibration engineer asks of a sensor.

Above ``features`` and ``verdict`` (recording resampling), below ``report``
and the CLI: pure functions on features.parquet and on signals, so the same
numbers feed ``sdt compare``, the report's "Severity and alarms" section and
a notebook.

Public API
----------
ZoneTable, load_zone_file, resolve_table, builtin_tables, grade, band_problem
    Zone tables as TOML data (ISO 10816-3 groups 1/2 rigid/flexible, ISO 20816-1
    typical ranges, or a plant's own; 10-1000 Hz, or 2-1000 Hz below 600 r/min),
    validated; ``band_problem`` says why windows cannot be graded by a table.
assign_tables, spec_tables, Assignment
    Which table grades which machine, and why: the machine's spec (MachineSpec,
    the dataset's or the user's), the config's ``zones``, ``--zones``.
zone_agreement(features, reference, assignments, bandwidths=) -> Agreement
    Zone agreement, zone confusion, dangerous (better-zone) share, criterion II
    alarm agreement on each sensor's own baseline (and on the reference's, beside)
    per machine, channel and sensor with recording-level intervals; the zone per
    condition (``condition_zones``); the V_RMS band each sensor covers (``vrms_bands``).
window_agreement(features, reference, assignments) -> DataFrame
    The pooled share of windows in the reference's zone per machine and sensor, no
    intervals (the objective ``sdt explore`` checks per design point).
RULE, CriterionII, alarm_thresholds, alarm_bits
    The criterion II rules (``criterion2.toml``, with clauses) and their thresholds.
defect_frequencies, defect_lines ; envelope_spectrum, velocity_spectrum, asd
    Bearing defect lines of a BearingSpec (``defect_lines``: a ball fault at 2 x BSF) and
    the spectra the field reads, with their scaling (the
    velocity spectrum's ``overall`` computed with the window's ENBW).
estimate_running_speed -> SpeedEstimate ; running_speed
    The shaft speed off the spectrum, away from mains lines, with its confidence
    (:mod:`sdt_framework.speed`, re-exported).
"""

from __future__ import annotations

from ..speed import MAINS_HZ, SpeedEstimate, estimate_running_speed, running_speed
from .agreement import NO_VRMS, Agreement, paired_zones, window_agreement, zone_agreement
from .alarms import ALARM_FRACTION, HEADROOM, RULE, CriterionII, alarm_bits, alarm_thresholds
from .assign import assign_tables, spec_tables
from .bands import band_label, sensor_bandwidths, vrms_bands
from .bearings import defect_frequencies, defect_lines, defect_orders
from .conditions import condition_zones
from .spectra import (
    LOW_EDGE_LINES,
    Spectrum,
    asd,
    chain_bandwidth,
    envelope_band,
    envelope_spectrum,
    velocity_spectrum,
)
from .tables import (
    ISO_BANDS_HZ,
    MACHINE_GROUPS,
    V_RMS_BAND_HZ,
    ZONES,
    Assignment,
    ZoneTable,
    band_problem,
    builtin_tables,
    grade,
    load_zone_file,
    resolve_table,
)

__all__ = [
    "ALARM_FRACTION",
    "HEADROOM",
    "ISO_BANDS_HZ",
    "LOW_EDGE_LINES",
    "MACHINE_GROUPS",
    "MAINS_HZ",
    "NO_VRMS",
    "RULE",
    "V_RMS_BAND_HZ",
    "ZONES",
    "Agreement",
    "Assignment",
    "CriterionII",
    "Spectrum",
    "SpeedEstimate",
    "ZoneTable",
    "alarm_bits",
    "alarm_thresholds",
    "asd",
    "assign_tables",
    "band_label",
    "band_problem",
    "builtin_tables",
    "chain_bandwidth",
    "condition_zones",
    "defect_frequencies",
    "defect_lines",
    "defect_orders",
    "envelope_band",
    "envelope_spectrum",
    "estimate_running_speed",
    "grade",
    "load_zone_file",
    "paired_zones",
    "resolve_table",
    "running_speed",
    "sensor_bandwidths",
    "spec_tables",
    "velocity_spectrum",
    "vrms_bands",
    "window_agreement",
    "zone_agreement",
]
