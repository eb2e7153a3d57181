"""ISO severity zones and alarms: what a vibration engineer asks of a sensor.

Above ``features`` and ``verdict`` (recording resampling), below ``report``
and the CLI: pure functions on features.parquet and on signals, so the same
numbers feed ``sdt compare``, the report's "Severity and alarms" section and
a notebook.

Public API
----------
ZoneTable, load_zone_file, resolve_table, builtin_tables, assign_tables, grade
    Zone tables as TOML data (ISO 10816-3 groups 1/2 rigid/flexible, ISO 20816-1
    typical ranges, or a plant's own), validated; which table grades which machine.
zone_agreement(features, reference, assignments) -> Agreement
    Zone agreement, zone confusion, dangerous (better-zone) share and criterion II
    alarm agreement per machine, channel and sensor, with recording-level intervals.
window_agreement(features, reference, assignments) -> DataFrame
    The pooled share of windows in the reference's zone per machine and sensor, no
    intervals (the objective ``sdt explore`` checks per design point).
defect_frequencies, BEARINGS ; envelope_spectrum, velocity_spectrum, asd, running_speed
    Bearing defect lines and the spectra the field reads, with their scaling.
"""

from __future__ import annotations

from .agreement import (
    ALARM_FRACTION,
    HEADROOM,
    Agreement,
    alarm_thresholds,
    paired_zones,
    window_agreement,
    zone_agreement,
)
from .bearings import BEARINGS, defect_frequencies, defect_orders
from .spectra import (
    Spectrum,
    asd,
    chain_bandwidth,
    envelope_band,
    envelope_spectrum,
    running_speed,
    velocity_spectrum,
)
from .tables import (
    DEFAULT_TABLES,
    MACHINE_GROUPS,
    ZONES,
    Assignment,
    ZoneTable,
    assign_tables,
    builtin_tables,
    grade,
    load_zone_file,
    resolve_table,
)

__all__ = [
    "ALARM_FRACTION",
    "BEARINGS",
    "DEFAULT_TABLES",
    "HEADROOM",
    "MACHINE_GROUPS",
    "ZONES",
    "Agreement",
    "Assignment",
    "Spectrum",
    "ZoneTable",
    "alarm_thresholds",
    "asd",
    "assign_tables",
    "builtin_tables",
    "chain_bandwidth",
    "defect_frequencies",
    "defect_orders",
    "envelope_band",
    "envelope_spectrum",
    "grade",
    "load_zone_file",
    "paired_zones",
    "resolve_table",
    "running_speed",
    "velocity_spectrum",
    "window_agreement",
    "zone_agreement",
]
