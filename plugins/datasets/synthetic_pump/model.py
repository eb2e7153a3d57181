"""Physical constants of the synthetic pump test rig: machines, bearings, paths, scatter.

The fault signatures are in ``faults.py``.

Everything the generator (``generate.py``) assumes is here, with its reason, so
that the documentation and the tests can compute the expected frequencies
independently of the generator. The levels are calibrated against published
statistics of the real NLN-EMP archive (docs/data.md, "Calibration";
``benchmarks/calibrate_synth.py`` prints each figure next to its source):

- [A] felcoslop/TP_CONFIABILIDADE@e73e8a85, code/resultados/tabelas/features.csv:
  band RMS of every 12 s acquisition of Motor-4 ch1/ch2/ch5 (10-200/300 Hz) and
  Motor-2 ch1 (1-9 kHz) for the healthy runs and several faults;
- [B] CYPHr007/PILAR@5252bc18, nln_emp_features.csv: overall RMS of Motor-2 ch1
  per acquisition for healthy, impeller and the three bearing faults;
- [M] the dataset's own metadata as read by public readers: motors MG160MA4
  (4-pole, Motor-2) and MG180MB2 (2-pole, Motor-4); Motor-4 at 70 % runs at
  2075 rpm ("measurement overview.xlsx", Speed (RPM) +- 5, via
  AKSHAJ-SHELL/pumpwatch src/pumpwatch/datasets/twente_raw.py); Motor-2 bearings
  6309.C4 (motor, faults at its NDE) and 6308.2Z.C3 (pump NDE);
- [P] the paper: Motor-2 at 100 % is 1480 rpm; cavitation suction 4 on ch1
  saturates the ADXL345 (+-16 g) but not the ADXL357 (+-40 g).

Where no source gives a figure the physical model is kept and the constant
says so ("no source").
"""

from __future__ import annotations

from dataclasses import dataclass

from sdt_framework.specs import BearingSpec

from ..pump_rig import rig_machines

__all__ = [
    "CHANNELS",
    "MACHINES",
    "MOTOR_BEARING",
    "NODE_AXES",
    "NODE_CHANNELS",
    "PUMP_BEARING",
    "VANES",
    "Bearing",
    "ChannelPath",
    "Machine",
    "channel_path",
    "levels_of",
]

#: columns (12 s each) per run in the real archive, as the data article gives them: an
#: acquisition is 60 s stored as five columns; healthy runs 12 acquisitions, faults 2-4
COLUMNS_PER_ACQUISITION = 5
REAL_COLUMNS = {"healthy": 60, "fault": 10}
#: the real reference chain: NI USB-4432, 24 bit, full scale +-50 g, band-pass 1 Hz-10 kHz
#: (the data article); the stored signals are clipped there
FULL_SCALE_G = 50.0

VANES = 6  # no source for either pump's vane count: kept


#: the rig's machines (``../pump_rig.toml``, each figure with its source [M], [P]): the
#: running speeds and the bearings whose defect rates the impacts follow
RIG = rig_machines()
Bearing = BearingSpec
MOTOR_BEARING, PUMP_BEARING = RIG["Motor-2"].bearings  # 6309 at the motor, 6308 at the pump


@dataclass(frozen=True)
class Machine:
    """A motor-pump set at one operating point, with its conditions and levels.

    ``MACHINES`` holds each at its paper point; ``speeds.machine_at`` the others, whose
    ``key`` (default: the name) names their random draws, so a run at another speed is
    another recording, and whose ``line_scale`` scales the shaft-synchronous lines.
    """

    name: str
    speed: str
    rpm: float
    conditions: tuple[tuple[str, int], ...]  # (class, number of levels / healthy runs)
    absent: frozenset[tuple[str, int]] = frozenset()  # levels the real archive does not hold
    key: str = ""  # the random draws' name for the machine at this speed ("": the name)
    line_scale: float = 1.0  # lines' acceleration over their level at the paper point

    @property
    def shaft_hz(self) -> float:
        """Nominal running speed, Hz."""
        return self.rpm / 60.0

    @property
    def draws(self) -> str:
        """The name the random draws of this machine's runs are keyed by."""
        return self.key or self.name


def _speed(name: str) -> tuple[str, float]:
    """The speed folder ("70") and running speed, rpm, of ``name`` in the rig's file."""
    return f"{RIG[name].speed_percent:g}", RIG[name].shaft_rpm


MACHINES: dict[str, Machine] = {
    "Motor-4": Machine(
        "Motor-4",
        *_speed("Motor-4"),  # [M]: 2-pole motor at 70 %, 2075 rpm
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
        # the real archive holds no "cavitation suction 2" for Motor-4 (its README)
        frozenset({("cavitation suction", 2)}),
    ),
    "Motor-2": Machine(
        "Motor-2",
        *_speed("Motor-2"),  # [P]: 4-pole motor at 100 %, 1480 rpm
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
    ``install_sd`` is the log-normal SD, from installation to installation, of
    the channel's response to the healthy machine's shaft-synchronous vibration
    (re-aligned, re-torqued, new flow set point): each healthy run is its own
    installation, the levels of a fault class share their campaign's.
    """

    name: str
    description: str
    gains: dict[str, complex]
    modes: tuple[tuple[float, float, float], ...]
    impacts: dict[str, float]
    cavitation: float
    install_sd: float


def _scaled(gains: dict[str, complex], k: float) -> dict[str, complex]:
    return {group: k * g for group, g in gains.items()}


# gains: the pattern between groups is the physical model's (no source); one factor
# per channel sets the healthy Motor-4 low band to [A] (ch1 10-300 Hz 0.094 g, ch2
# and ch5 10-200 Hz 0.049 and 0.089 g); ch3 and ch4 (no source) take ch1's factor.
# install_sd: chosen so that the CV of three healthy runs is typically [A]'s (ch1
# 0.091, ch2 0.385, ch5 0.045); ch3 and ch4 (no source) take ch1's.
CHANNELS: dict[str, ChannelPath] = {
    "ch1": ChannelPath(
        "ch1",
        "motor non-drive-end horizontal",
        _scaled(
            {"motor_radial": 1.0, "motor_axial": 0.15, "pump_radial": 0.3, "pump_axial": 0.05}, 3.1
        ),
        ((2900.0, 0.04, 1.0), (6800.0, 0.05, 0.5)),
        {"motor_bearing": 0.6, "pump_bearing": 0.15, "coupling": 0.5},
        0.8,
        0.10,
    ),
    "ch2": ChannelPath(
        "ch2",
        "motor drive-end vertical",
        _scaled(
            {"motor_radial": 0.9j, "motor_axial": 0.15, "pump_radial": 0.45j, "pump_axial": 0.05},
            2.1,
        ),
        ((3600.0, 0.035, 1.0), (5200.0, 0.05, 0.6)),
        {"motor_bearing": 1.0, "pump_bearing": 0.25, "coupling": 1.0},
        0.7,
        0.45,
    ),
    "ch3": ChannelPath(
        "ch3",
        "motor drive-end axial",
        _scaled(
            {"motor_radial": 0.25, "motor_axial": 1.0, "pump_radial": 0.1, "pump_axial": 0.4}, 3.1
        ),
        ((2400.0, 0.04, 1.0), (7400.0, 0.05, 0.4)),
        {"motor_bearing": 0.7, "pump_bearing": 0.2, "coupling": 0.7},
        0.6,
        0.09,
    ),
    "ch4": ChannelPath(
        "ch4",
        "pump drive-end horizontal",
        _scaled(
            {"motor_radial": 0.4, "motor_axial": 0.05, "pump_radial": 1.0, "pump_axial": 0.15}, 3.1
        ),
        ((4300.0, 0.04, 1.0), (6100.0, 0.045, 0.6)),
        {"motor_bearing": 0.2, "pump_bearing": 1.0, "coupling": 0.9},
        1.0,
        0.09,
    ),
    "ch5": ChannelPath(
        "ch5",
        "pump non-drive-end vertical",
        _scaled(
            {"motor_radial": 0.25j, "motor_axial": 0.05, "pump_radial": 0.9j, "pump_axial": 0.15},
            4.8,
        ),
        ((3200.0, 0.035, 1.0), (8200.0, 0.05, 0.4)),
        {"motor_bearing": 0.15, "pump_bearing": 0.8, "coupling": 0.4},
        0.9,
        0.045,
    ),
}

#: The triaxial node (dataset option ``triaxial = true``, off by default so the paper's
#: five channels stay as they are): a MEMS node on the motor drive-end bearing housing
#: reads vertical and axial where ch2 and ch3 do and adds the horizontal axis, ch6,
#: through the same physics: a horizontal sensor sees the rotating force 90 degrees from
#: the vertical one (real gain where ch2's is imaginary), the drive-end housing's
#: resonances and impacts as ch2 (one housing), and ch1's horizontal factor, install
#: spread and cavitation weight (no source). Node: x = ch6, y = ch2, z = ch3.
NODE_CHANNELS: dict[str, ChannelPath] = {
    "ch6": ChannelPath(
        "ch6",
        "motor drive-end horizontal (triaxial node)",
        _scaled(
            {"motor_radial": 0.9, "motor_axial": 0.15, "pump_radial": 0.45, "pump_axial": 0.05},
            3.1,
        ),
        CHANNELS["ch2"].modes,
        CHANNELS["ch2"].impacts,
        0.8,
        0.10,
    ),
}
NODE_AXES = {"ch6": "x", "ch2": "y", "ch3": "z"}


def levels_of(machine: Machine, condition: str, levels: int) -> tuple[int, ...]:
    """The levels of ``condition`` that ``machine``'s runs hold (healthy: the run numbers)."""
    return tuple(k for k in range(1, levels + 1) if (condition, k) not in machine.absent)


def channel_path(name: str) -> ChannelPath:
    """The path of ``name``, looked up at call time (a test may replace a path)."""
    return CHANNELS[name] if name in CHANNELS else NODE_CHANNELS[name]


#: healthy baseline harmonics: (group, shaft order, amplitude g); pattern: no source
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

# broadband flow/structure noise, RMS per unit mode weight: Motor-2 ch1 healthy overall
# RMS 0.53 g, 96 % of it in 1-9 kHz [A, B]; Motor-4 (no source) takes the same
FLOW_NOISE_G = 0.47
SENSOR_NOISE_G = 0.004  # RMS of independent broadband noise per channel
SPEED_JITTER = 0.002  # relative SD of run speed (clipped at 3 SD): [M] says +- 5 rpm
AMPLITUDE_SCATTER = 0.01  # log-normal SD of run-to-run source strength (clipped at 2 SD)
# broadband level per installation, log-normal SD: healthy run-to-run CV 0.21 [B], 0.32 [A]
# (Motor-2 ch1, every channel alike) split into the operating point, shared by every
# channel (flow and pressure set by the valves: flow noise grows with the distance from the
# best-efficiency point), and each channel's mounting (its resonances' coupling to the casing)
FLOW_POINT_SD = 0.24
HF_MOUNT_SD = 0.12
# vane-pass pulsation ~ operating point ** exponent: both it and the flow noise grow away
# from the best-efficiency flow (Brennen, "Hydrodynamics of Pumps", ch. 9); exponent: no source
VANE_PASS_EXPONENT = 1.0
# a fault level around its campaign (log-normal SD: shaft-synchronous, broadband): [A]'s
# unbalance motor levels 1-4 spread by CV 0.062 in ch2's low band; the broadband of a
# class's runs stays on its trajectory (impeller's fall with damage: [B], FLOW_TREND)
LEVEL_SCATTER = (0.05, 0.02)
ACQUISITION_DRIFT = 0.03  # between acquisitions of a run: CV 0.026 [A], 0.04 [B]
