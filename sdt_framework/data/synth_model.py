"""Physical constants of the synthetic pump test rig: machines, bearings, paths, faults.

Everything the generator (``synth.py``) assumes is here, with its reason, so
that the documentation and the tests can compute the expected frequencies
independently of the generator.

Choices (documented in docs/data.md):

- Rated speed 1480 rpm (4-pole induction motor on 50 Hz, as Motor-2 at 100 %).
  Motor-4 runs at 70 %: 0.7 x 1480 = 1036 rpm (17.27 Hz).
- Pump impeller with 6 vanes: vane pass = 6 x shaft speed.
- Motor bearings SKF 6206 (9 balls, d = 9.525 mm, pitch D = 46 mm, 0 deg);
  pump bearing 6307 (8 balls, d = 13.494 mm, D = 58.5 mm). Outer/inner race
  defect frequencies BPFO/BPFI = n/2 (1 -/+ d/D cos a) x shaft speed.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = [
    "CHANNELS",
    "MACHINES",
    "MOTOR_BEARING",
    "PUMP_BEARING",
    "VANES",
    "Bearing",
    "ChannelPath",
    "Machine",
]

RATED_RPM = 1480.0
VANES = 6


@dataclass(frozen=True)
class Bearing:
    """Rolling-element bearing geometry; defect frequencies as multiples of shaft speed."""

    name: str
    balls: int
    ball_mm: float
    pitch_mm: float

    @property
    def bpfo(self) -> float:
        """Ball pass frequency, outer race, per shaft revolution."""
        return self.balls / 2 * (1 - self.ball_mm / self.pitch_mm)

    @property
    def bpfi(self) -> float:
        """Ball pass frequency, inner race, per shaft revolution."""
        return self.balls / 2 * (1 + self.ball_mm / self.pitch_mm)


MOTOR_BEARING = Bearing("6206", 9, 9.525, 46.0)
PUMP_BEARING = Bearing("6307", 8, 13.494, 58.5)


@dataclass(frozen=True)
class Machine:
    """A motor-pump set at one operating point, with its conditions and levels."""

    name: str
    speed: str
    rpm: float
    conditions: tuple[tuple[str, int], ...]  # (class, number of levels / healthy runs)

    @property
    def shaft_hz(self) -> float:
        """Nominal running speed, Hz."""
        return self.rpm / 60.0


MACHINES: dict[str, Machine] = {
    "Motor-4": Machine(
        "Motor-4",
        "70",
        0.7 * RATED_RPM,
        (
            ("healthy", 3),
            ("unbalance motor", 6),
            ("unbalance pump", 3),
            ("align angular", 5),
            ("align parallel", 4),
            ("align combination", 4),
            ("coupling", 3),
            ("cavitation suction", 4),
            ("cavitation discharge", 5),
        ),
    ),
    "Motor-2": Machine(
        "Motor-2",
        "100",
        RATED_RPM,
        (
            ("healthy", 3),
            ("impeller", 3),
            ("bearing bpfo", 3),
            ("bearing bpfi", 3),
            ("bearing pump", 3),
        ),
    ),
}


@dataclass(frozen=True)
class ChannelPath:
    """Transfer path from the rig's sources to one accelerometer.

    ``gains`` maps a low-frequency source group (location, direction) to a
    complex gain (amplitude and phase at the sensor); horizontal and vertical
    sensors see a rotating force 90 degrees apart. ``modes`` are the kHz
    structural resonances (frequency Hz, damping ratio, weight) that impacts
    and flow noise excite; ``impacts`` weights each impact source by distance.
    """

    name: str
    description: str
    gains: dict[str, complex]
    modes: tuple[tuple[float, float, float], ...]
    impacts: dict[str, float]
    cavitation: float


CHANNELS: dict[str, ChannelPath] = {
    "ch1": ChannelPath(
        "ch1",
        "motor non-drive-end horizontal",
        {"motor_radial": 1.0, "motor_axial": 0.15, "pump_radial": 0.3, "pump_axial": 0.05},
        ((2900.0, 0.04, 1.0), (6800.0, 0.05, 0.5)),
        {"motor_bearing": 0.6, "pump_bearing": 0.15, "coupling": 0.5},
        0.8,
    ),
    "ch2": ChannelPath(
        "ch2",
        "motor drive-end vertical",
        {"motor_radial": 0.9j, "motor_axial": 0.15, "pump_radial": 0.45j, "pump_axial": 0.05},
        ((3600.0, 0.035, 1.0), (5200.0, 0.05, 0.6)),
        {"motor_bearing": 1.0, "pump_bearing": 0.25, "coupling": 1.0},
        0.7,
    ),
    "ch3": ChannelPath(
        "ch3",
        "motor drive-end axial",
        {"motor_radial": 0.25, "motor_axial": 1.0, "pump_radial": 0.1, "pump_axial": 0.4},
        ((2400.0, 0.04, 1.0), (7400.0, 0.05, 0.4)),
        {"motor_bearing": 0.7, "pump_bearing": 0.2, "coupling": 0.7},
        0.6,
    ),
    "ch4": ChannelPath(
        "ch4",
        "pump drive-end horizontal",
        {"motor_radial": 0.4, "motor_axial": 0.05, "pump_radial": 1.0, "pump_axial": 0.15},
        ((4300.0, 0.04, 1.0), (6100.0, 0.045, 0.6)),
        {"motor_bearing": 0.2, "pump_bearing": 1.0, "coupling": 0.9},
        1.0,
    ),
    "ch5": ChannelPath(
        "ch5",
        "pump non-drive-end vertical",
        {"motor_radial": 0.25j, "motor_axial": 0.05, "pump_radial": 0.9j, "pump_axial": 0.15},
        ((3200.0, 0.035, 1.0), (8200.0, 0.05, 0.4)),
        {"motor_bearing": 0.15, "pump_bearing": 0.8, "coupling": 0.4},
        0.9,
    ),
}

#: healthy baseline harmonics: (group, shaft order, amplitude g)
BASELINE: tuple[tuple[str, float, float], ...] = (
    ("motor_radial", 1, 0.04),
    ("motor_radial", 2, 0.015),
    ("motor_radial", 3, 0.006),
    ("pump_radial", 1, 0.035),
    ("pump_radial", VANES, 0.06),
    ("pump_radial", 2 * VANES, 0.02),
    ("motor_axial", 1, 0.015),
    ("pump_axial", 1, 0.012),
    ("pump_axial", VANES, 0.02),
)

#: fault harmonics added per severity level: class -> (group, order, g per level)
FAULT_HARMONICS: dict[str, tuple[tuple[str, float, float], ...]] = {
    "unbalance motor": (("motor_radial", 1, 0.08),),
    "unbalance pump": (("pump_radial", 1, 0.10),),
    "align parallel": (
        ("motor_radial", 2, 0.06),
        ("pump_radial", 2, 0.05),
        ("motor_radial", 1, 0.02),
        ("motor_axial", 2, 0.01),
    ),
    "align angular": (
        ("motor_axial", 1, 0.07),
        ("pump_axial", 1, 0.05),
        ("motor_axial", 2, 0.04),
        ("motor_radial", 1, 0.015),
    ),
    "align combination": (
        ("motor_radial", 2, 0.042),
        ("pump_radial", 2, 0.035),
        ("motor_axial", 1, 0.05),
        ("pump_axial", 1, 0.035),
        ("motor_axial", 2, 0.028),
        ("motor_radial", 1, 0.025),
    ),
    "coupling": (
        ("motor_radial", 1, 0.02),
        ("motor_radial", 2, 0.03),
        ("motor_radial", 3, 0.025),
        ("pump_radial", 3, 0.015),
    ),
    "impeller": (
        ("pump_radial", VANES, 0.08),
        ("pump_radial", 2 * VANES, 0.03),
        ("pump_radial", 1, 0.03),
    ),
    "bearing pump": (("pump_radial", 1, 0.02),),
}

#: cavitation bursts: class -> (peak amplitude g at level 1..L, bursts per second)
CAVITATION: dict[str, tuple[tuple[float, ...], tuple[float, ...]]] = {
    "cavitation suction": ((0.8, 2.0, 4.5, 9.0), (8.0, 12.0, 16.0, 20.0)),
    "cavitation discharge": ((0.5, 0.7, 0.95, 1.25, 1.6), (6.0, 8.0, 10.0, 12.0, 14.0)),
}

#: bearing impacts: class -> (bearing location, bearing, race, impact g per level)
BEARING_FAULTS: dict[str, tuple[str, Bearing, str, float]] = {
    "bearing bpfo": ("motor_bearing", MOTOR_BEARING, "outer", 0.5),
    "bearing bpfi": ("motor_bearing", MOTOR_BEARING, "inner", 0.6),
    "bearing pump": ("pump_bearing", PUMP_BEARING, "outer", 1.5),
}

COUPLING_IMPACT_G = 0.35  # g per level, two impacts per revolution (jaw coupling, worn spider)
FLOW_NOISE_G = 0.012  # RMS of flow turbulence through the structure (all classes)
SENSOR_NOISE_G = 0.004  # RMS of independent broadband noise per channel
SPEED_JITTER = 0.002  # relative SD of run speed (clipped at 3 SD)
AMPLITUDE_SCATTER = 0.03  # log-normal SD of run-to-run amplitude (clipped at 2 SD)
BEARING_SLIP = 0.01  # relative SD of the interval between bearing impacts
CAVITATION_BURST_S = 0.006  # decay time constant of one cavitation burst envelope
CAVITATION_HISS = 0.2  # continuous cavitation noise, as a fraction of the burst amplitude
CAVITATION_BAND_HZ = (2000.0, 8000.0)
