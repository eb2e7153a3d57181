"""Zone agreement of every design point with the reference: the objective beside Macro F1.

``zone_agreement = 0.95`` under a sweep's ``[sweep.target]`` asks that a point
grade the machine as the reference does in 95 % of windows: each window's
V_RMS (10-1000 Hz, mm/s) is graded in ISO zones A-D by its machine's zone
table and paired with the reference's same window, by the severity package's
own grading (:func:`sdt_framework.severity.window_agreement`, the figure ``sdt
compare`` and the report give, pooled over channels). It needs the features
only, repetition 0 as features.parquet holds them, and no classifier, so it
costs a merge per sweep. This module attaches the share to the exploration
table, one value per point and machine; :mod:`.objectives` decides pass or fail.
"""

from __future__ import annotations

import pandas as pd

from ..bench.plan import Plan
from ..errors import SDTError
from ..severity import Assignment, assign_tables, window_agreement
from .target import Target

__all__ = ["point_zone_agreement", "with_zone_agreement", "zone_assignments"]


def zone_assignments(plan: Plan, where: str, every: bool = True) -> dict[str, Assignment]:
    """The zone table of each machine ``plan`` uses (the config's ``zones``, else the one
    its machine spec names: ``plan.machines``).

    A bad ``zones`` entry is one line naming ``where``; with ``every``, so is
    a machine without a table (the target cannot be judged there).
    """
    machines = sorted({r.machine for r in plan.recordings})
    zones_where = f"{where}: [benchmark] zones"
    assignments = assign_tables(
        machines, configured=plan.config.zones, where=zones_where, specs=plan.machines
    )
    missing = [m for m in machines if m not in assignments]
    if every and missing:
        raise SDTError(
            f"{where}: target.zone_agreement needs a zone table for machine(s) "
            f"{', '.join(missing)}; name one in [benchmark] zones, e.g. zones = "
            f'{{ "{missing[0]}" = "iso10816-3-group2-rigid" }}, or as zone_table in its '
            f"machine spec (docs/severity.md)"
        )
    return assignments


def point_zone_agreement(
    features: pd.DataFrame, reference: str, assignments: dict[str, Assignment]
) -> pd.DataFrame:
    """``point``, ``machine``, ``zone_agreement`` (share of windows in the reference's zone)."""
    if "repeat" in features.columns:
        features = features[features["repeat"] == 0]  # the windows features.parquet holds
    shares = window_agreement(features, reference, assignments)
    return shares.rename(columns={"sensor": "point"})[["point", "machine", "zone_agreement"]]


def with_zone_agreement(
    table: pd.DataFrame, features: pd.DataFrame, plan: Plan, target: Target
) -> pd.DataFrame:
    """``table`` with a ``zone_agreement`` column when ``target`` asks for it (else as given).

    The reference agrees with itself on every window (1.0).
    """
    if target.zone_agreement is None:
        return table
    shares = point_zone_agreement(features, plan.reference, zone_assignments(plan, "sweep"))
    out = table.drop(columns="zone_agreement", errors="ignore")
    out = out.merge(shares, on=["point", "machine"], how="left")
    out.loc[out["role"] == "reference", "zone_agreement"] = 1.0
    return out
