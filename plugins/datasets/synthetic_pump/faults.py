"""Fault signatures of the synthetic pump: what each fault adds, where, and how it grows.

A fault is recognisable on the real rig because it has a signature that stays
the same in kind across its severities: a line at 1x or 2x running speed, an
axial share, an impact train at a bearing's defect rate ringing the casing
resonances, a broadband kHz hump with bursts. Each constant below says what
it models, why (the physics, textbook diagnostics), and which figure of the
real archive it is calibrated on (the letters are ``model``'s sources
[A], [B], [M], [P]) or "no source" when only the physics fixes it. The
generator (``generate.py``) places each signature on the source group where the
fault acts (motor or pump, radial or axial, motor or pump bearing, coupling,
impeller eye, discharge); the channels see it through their transfer paths.

Physics (textbook vibration diagnostics, e.g. R.B. Randall, "Vibration-based
Condition Monitoring", Wiley 2011, ch. 2 and 5; J. Piotrowski, "Shaft
Alignment Handbook", 3rd ed. 2007, ch. 1; C.E. Brennen, "Hydrodynamics of
Pumps", 1994, ch. 5-7; D.R. McKee et al., "A review of machinery diagnostics
and prognostics implemented on a centrifugal pump", 2011):

- unbalance: a once-per-revolution rotating force, a 1x radial line growing
  with the added mass (vector sum with the residual unbalance);
- misalignment: parallel offset gives 2x radial, angular gives 1x (and 2x)
  axial; both load the coupling;
- worn coupling (elastomer spider): backlash impacts twice per revolution and
  1x-3x radial lines;
- rolling-element bearing defects: impacts at the defect rate (BPFO, BPFI)
  exciting the casing resonances (kurtosis, crest factor, envelope lines), the
  inner race amplitude-modulated at 1x by the load zone;
- suction cavitation: vapour cavities collapsing at the impeller eye as the
  vanes pass: kHz bursts (high kurtosis) whose rate and strength grow as the
  suction pressure falls;
- discharge throttling: the pump runs far below its best-efficiency flow:
  recirculation gives random sub-synchronous forces on the impeller, and the
  throttled valve a continuous kHz hiss (no bursts: kurtosis stays near 3);
- impeller damage: a changed vane-pass force and hydraulic unbalance (1x pump).
"""

from __future__ import annotations

from .model import MOTOR_BEARING, PUMP_BEARING, VANES, Bearing

__all__ = [
    "CAVITATION",
    "DISCHARGE",
    "FAULT_HARMONICS",
    "IMPACTS",
    "IMPACT_STEPS",
    "SEVERITY_STEPS",
]

#: shaft-synchronous lines added per severity level: class -> (group, order, g per level).
#: Unbalance and parallel misalignment: set by [A]'s growth of band RMS with severity (ch2,
#: ch5, ch1); angular: scaled down until its low band stays inside the healthy spread, as
#: [A] reports, its growth on the axial channel; coupling, impeller, pump bearing: no source.
FAULT_HARMONICS: dict[str, tuple[tuple[str, float, float], ...]] = {
    "unbalance motor": (("motor_radial", 1, 0.0425),),
    "unbalance pump": (("pump_radial", 1, 0.005),),
    "align parallel": (
        ("motor_radial", 2, 0.032),
        ("pump_radial", 2, 0.027),
        ("motor_radial", 1, 0.011),
        ("motor_axial", 2, 0.0053),
    ),
    "align angular": (
        ("motor_axial", 1, 0.014),
        ("pump_axial", 1, 0.01),
        ("motor_axial", 2, 0.008),
        ("motor_radial", 1, 0.003),
    ),
    "coupling": (
        ("motor_radial", 1, 0.02),
        ("motor_radial", 2, 0.03),
        ("motor_radial", 3, 0.025),
        ("pump_radial", 3, 0.015),
    ),
    "impeller": (
        ("pump_radial", VANES, 0.03),
        ("pump_radial", 2 * VANES, 0.03),
        ("pump_radial", 1, 0.03),
    ),
    "bearing pump": (
        ("pump_radial", 1, 0.015),
        ("pump_radial", 2, 0.008),
        ("pump_radial", 3, 0.005),
    ),
}
# combination: 70 % of parallel plus 70 % of angular (no source)
FAULT_HARMONICS["align combination"] = tuple(
    (group, order, 0.7 * amp)
    for name in ("align parallel", "align angular")
    for group, order, amp in FAULT_HARMONICS[name]
)

#: effective size of each level where the levels are not equal steps (default: the level
#: number): [A]'s unbalance motor levels 1-4 leave ch2's low band within 6 % of each
#: other (0.034-0.039 g), levels 5 and 6 raise it 1.9 and 2.6 times
SEVERITY_STEPS: dict[str, tuple[float, ...]] = {
    "unbalance motor": (0.025, 0.05, 0.075, 0.1, 1.6, 2.4),
    "bearing pump": (3.0, 3.3, 3.6),
}

#: log change of the flow noise per level: [B]'s Motor-2 ch1 overall RMS falls with impeller
#: damage (0.429, 0.395, 0.373 g): a damaged impeller delivers less head and flow
FLOW_TREND: dict[str, float] = {"impeller": -0.085}

#: impact trains: class -> (source, bearing, race, g per unit size) at a bearing's defect
#: rate, or (source, None, impacts per revolution, g per unit size) for a shaft-locked
#: knock. Motor bearing: set by [B]'s growth of ch1 overall RMS with severity. Pump
#: bearing: damage introduced at assembly, severe from level 1 (the paper: "high vibration
#: energy"); no source for the pump channels, its ch1 level matches [B]. Coupling: a worn
#: spider knocks twice per revolution from the first level (backlash), growing slowly;
#: impeller: a damaged vane's pressure pulse as it passes the cutwater, once per
#: revolution, on the pump casing. Both: no source.
IMPACTS: dict[str, tuple[str, Bearing | None, str | float, float]] = {
    "bearing bpfo": ("motor_bearing", MOTOR_BEARING, "outer", 1.0),
    "bearing bpfi": ("motor_bearing", MOTOR_BEARING, "inner", 2.0),
    "bearing pump": ("pump_bearing", PUMP_BEARING, "outer", 1.5),
    "coupling": ("coupling", None, 2.0, 0.4),
    "impeller": ("pump_bearing", None, 1.0, 0.5),
}
#: impact size per level (default: the level number). Motor bearings: seeded defects,
#: present from level 1 and twice as large at level 3, as [B]'s ch1 overall RMS grows
#: from level 1 to 3 by only 1.34 (BPFI) and 1.13 (BPFO)
IMPACT_STEPS: dict[str, tuple[float, ...]] = {
    "bearing pump": (3.0, 3.3, 3.6),
    "coupling": (2.5, 3.0, 3.5),
    "bearing bpfo": (1.5, 2.25, 3.0),
    "bearing bpfi": (1.5, 2.25, 3.0),
}
BEARING_SLIP = 0.01  # relative SD of the interval between bearing impacts
KNOCK_SCATTER = 0.2  # relative SD of one shaft-locked knock's strength (coupling, impeller)

#: suction cavitation bursts: class -> (peak g at level 1..L, bursts per second). Level 4
#: set by [P]: ch1 saturates the ADXL345 but not the ADXL357 and stays inside the
#: reference's +-80 g. Levels 1-3: cavitation is developed from the first level (it is
#: audible at each of the rig's settings): bursts dominate the kHz band at every level,
#: so their kurtosis is the class's mark; rate and strength grow as suction pressure falls.
CAVITATION: dict[str, tuple[tuple[float, ...], tuple[float, ...]]] = {
    "cavitation suction": ((7.5, 8.0, 8.5, 9.5), (14.0, 16.0, 18.0, 20.0)),
}
CAVITATION_BURST_S = 0.006  # decay time constant of one cavitation burst envelope
CAVITATION_HISS = 0.1  # continuous cavitation noise, as a fraction of the burst amplitude
CAVITATION_BAND_HZ = (1000.0, 5000.0)  # low enough to clip the ADXL345, peaks < 80 g [P]

#: discharge throttling: class -> (continuous hiss RMS g, recirculation force RMS g on the
#: pump's radial group) per level; no source: the hiss about doubles the broadband level
#: from the first level (the valve cavitates at every setting), the recirculation is of
#: the order of the residual pump 1x (ch5 about 12 mm/s); both grow as the valve closes
DISCHARGE: dict[str, tuple[tuple[float, ...], tuple[float, ...]]] = {
    "cavitation discharge": (
        (1.0, 1.05, 1.1, 1.15, 1.2),
        (0.03, 0.032, 0.034, 0.036, 0.038),
    ),
}
#: the throttled valve's broadband noise: from a few hundred Hz (turbulence at the valve)
#: into the kHz (vapour collapsing behind it), so it reaches the velocity band
DISCHARGE_BAND_HZ = (200.0, 5000.0)
#: recirculation band, in orders of running speed: random sub-synchronous forces
RECIRCULATION_ORDERS = (0.2, 0.8)

#: classes measured in one session, at one operating point (flow noise). Motor-2's four
#: faults: [B]'s ch1 overall RMS of their first levels lies within 0.43-0.47 g (CV 0.04)
#: while the three healthy runs spread over 0.41-0.62 g. The misalignments: set by moving
#: the motor on shims, the pump, pipework and valves untouched (no source for the session
#: plan; the paper finds the three confused with each other)
SESSIONS: dict[str, str] = {
    "impeller": "Motor-2 faults",
    "bearing bpfo": "Motor-2 faults",
    "bearing bpfi": "Motor-2 faults",
    "bearing pump": "Motor-2 faults",
    "align angular": "alignment",
    "align parallel": "alignment",
    "align combination": "alignment",
}
#: sessions that keep the sensors' mounting and the machine's installation: a faulty
#: bearing or impeller is exchanged with the sensors in place (motor end shield, pump
#: back pull-out), while a misalignment moves the motor and its feet's contact
MOUNTING_KEPT = frozenset({"Motor-2 faults"})
