"""Bearing defect frequencies from geometry: BPFO, BPFI, BSF, FTF as orders of shaft speed.

A bearing is a :class:`~sdt_framework.specs.BearingSpec` of the machine the
recordings come from: the dataset's machines (the pump rig's 6309 and 6308,
with their sources, in the pump datasets' ``pump_rig.toml``), a
``machines.toml`` beside a manifest or the benchmark config's
``machine_specs``. The formulas (deep-groove ball bearing, contact angle a):
BPFO = n/2 (1 - d/D cos a), BPFI = n/2 (1 + d/D cos a),
BSF = D/(2d) (1 - (d/D cos a)^2), FTF = 1/2 (1 - d/D cos a), are the spec's own.
"""

from __future__ import annotations

from ..specs import BearingSpec

__all__ = ["defect_frequencies", "defect_lines", "defect_orders"]


def defect_orders(bearing: BearingSpec) -> dict[str, float]:
    """BPFO, BPFI, BSF and FTF of ``bearing`` as multiples of the shaft speed."""
    return {"BPFO": bearing.bpfo, "BPFI": bearing.bpfi, "BSF": bearing.bsf, "FTF": bearing.ftf}


def defect_frequencies(bearing: BearingSpec, shaft_hz: float) -> dict[str, float]:
    """The four defect frequencies in Hz at shaft speed ``shaft_hz``."""
    return {name: order * shaft_hz for name, order in defect_orders(bearing).items()}


def defect_lines(bearing: BearingSpec, shaft_hz: float) -> dict[str, float]:
    """The lines an envelope spectrum shows a fault of each part at, in Hz: BPFO, BPFI,
    2×BSF and FTF.

    A defect on a ball strikes the inner and the outer race in turn, once each per
    spin revolution, so its envelope shows 2 x BSF most clearly, not BSF (1 x BSF is
    the ball's spin, not its impact rate). Sources: the Case Western Reserve
    University Bearing Data Center's table for its drive-end 6205-2RS JEM SKF gives
    the defect frequencies as multiples of running speed: inner ring 5.4152, outer
    ring 3.5848, cage 0.39828, rolling element 4.7135; its own BPFI and BPFO give
    n = 9 balls and d/D = 0.20338, so BSF = D/2d (1 - (d/D)^2) = 2.3568 and the
    rolling-element entry is 2.000 x BSF (the table read through public repository
    copies of it; tests/report/test_report_envelope_resonance.py recomputes it);
    vibromera.eu glossary "BSF"; bacdanvongbi.com "BSF": "2xBSF is the most
    prominent, because the rolling element contacts both rings once per
    revolution". The other three are :func:`defect_frequencies`' lines.
    """
    lines = defect_frequencies(bearing, shaft_hz)
    return {
        "BPFO": lines["BPFO"],
        "BPFI": lines["BPFI"],
        "2×BSF": 2 * lines["BSF"],
        "FTF": lines["FTF"],
    }
