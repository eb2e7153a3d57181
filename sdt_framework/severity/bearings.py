"""Bearing defect frequencies from geometry: BPFO, BPFI, BSF, FTF as orders of shaft speed.

The pump's bearings are named by the NLN-EMP metadata (docs/data.md, [M]):
motor 6309 (faults seeded at its non-drive end) and pump 6308. Their internal
geometry (8 balls of 17.46 / 15.08 mm on a 72.5 / 65.0 mm pitch circle, the
pitch taken as the mean of bore and outside diameter) is the one the synthetic
pump is built with (:mod:`sdt_framework.data.synth_model`), so the lines drawn
are the ones the generator's impacts follow; docs/severity.md says how far that
geometry is sourced (an approximation: no manufacturer's internal dimensions
were found). Formulas for a deep-groove ball bearing, contact angle 0:
BPFO = n/2 (1 - d/D), BPFI = n/2 (1 + d/D), BSF = D/(2d) (1 - (d/D)^2),
FTF = 1/2 (1 - d/D).
"""

from __future__ import annotations

from ..data.synth_model import MOTOR_BEARING, PUMP_BEARING, Bearing

__all__ = ["BEARINGS", "defect_frequencies", "defect_lines", "defect_orders"]

#: the bearings of the NLN-EMP / synthetic pump, by designation
BEARINGS: dict[str, Bearing] = {MOTOR_BEARING.name: MOTOR_BEARING, PUMP_BEARING.name: PUMP_BEARING}


def defect_orders(bearing: Bearing) -> dict[str, float]:
    """BPFO, BPFI, BSF and FTF of ``bearing`` as multiples of the shaft speed."""
    ratio = bearing.ball_mm / bearing.pitch_mm
    return {
        "BPFO": bearing.balls / 2 * (1 - ratio),
        "BPFI": bearing.balls / 2 * (1 + ratio),
        "BSF": bearing.pitch_mm / (2 * bearing.ball_mm) * (1 - ratio**2),
        "FTF": 0.5 * (1 - ratio),
    }


def defect_frequencies(bearing: Bearing, shaft_hz: float) -> dict[str, float]:
    """The four defect frequencies in Hz at shaft speed ``shaft_hz``."""
    return {name: order * shaft_hz for name, order in defect_orders(bearing).items()}


def defect_lines(bearing: Bearing, shaft_hz: float) -> dict[str, float]:
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
