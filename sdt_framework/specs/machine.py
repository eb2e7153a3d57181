"""MachineSpec: the machine a dataset's recordings come from, as data.

A machine is what severity and the report need to read its spectra: the shaft
speed the recordings run at, its bearings with their geometry (so the defect
lines can be placed), the channel nearest each bearing and the condition
labels that are faults of it, and the ISO zone table that grades it with the
reason it was chosen. Motor-2 and Motor-4 of the pump rig are one TOML file
the two pump datasets expose; a user's own machine is a file of the same form
(``machines.toml`` beside a manifest, or the benchmark config's
``machine_specs``), read by :mod:`sdt_framework.machine_files`.

Speed: ``shaft_rpm`` is the running speed at the one operating point the
recordings were taken at, ``speed_percent`` that point in % of the rated
speed and ``rated_rpm`` the rated speed, where a source gives them. A
recording that carries its own operating speed (variable speed, issue 43)
is read against ``rated_rpm``; until then every recording of a machine runs at
``shaft_rpm``.

Every value a user writes is checked here, one line each: a missing field, a
number written as text or a boolean, a bearing whose balls are not smaller
than its pitch circle or do not fit around it.
"""

from __future__ import annotations

import math
from typing import Annotated, Any

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, field_validator, model_validator

__all__ = ["BearingSpec", "MachineSpec", "OperatingPoint"]


def _number(value: Any) -> Any:
    """``value`` if it is a number; ``true`` or ``"1480"`` is refused, never read as one."""
    if isinstance(value, bool):
        raise ValueError(f"must be a number, got the boolean {str(value).lower()}")
    if isinstance(value, str):
        raise ValueError(f"must be a number, got the string {value!r}: drop the quotes")
    return value


Number = Annotated[float, BeforeValidator(_number)]
Count = Annotated[int, BeforeValidator(_number)]


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)


class BearingSpec(_Model):
    """A rolling-element bearing: geometry, where it sits, which faults of the data are its own.

    Defect frequencies as orders of shaft speed (contact angle a, ball
    diameter d, pitch diameter D, n balls): BPFO = n/2 (1 - d/D cos a),
    BPFI = n/2 (1 + d/D cos a), BSF = D/(2d) (1 - (d/D cos a)^2),
    FTF = (1 - d/D cos a)/2.
    """

    name: str = Field(min_length=1, description="Designation, e.g. '6309'.")
    location: str = Field(default="", description="Where it sits, e.g. 'motor non-drive end'.")
    balls: Count = Field(ge=3, description="Number of rolling elements.")
    ball_mm: Number = Field(gt=0, description="Rolling-element diameter d, mm.")
    pitch_mm: Number = Field(gt=0, description="Pitch-circle diameter D, mm.")
    contact_angle_deg: Number = Field(default=0.0, ge=0, lt=90, description="Contact angle.")
    channel: str = Field(min_length=1, description="The channel nearest the bearing.")
    faults: tuple[str, ...] = Field(
        description="Condition labels of the data that are faults of this bearing."
    )
    source: str = Field(default="", description="Where the designation and geometry come from.")

    @model_validator(mode="after")
    def _fits(self) -> BearingSpec:
        if self.ball_mm >= self.pitch_mm:
            raise ValueError(
                f"bearing {self.name!r}: ball_mm {self.ball_mm:g} >= pitch_mm {self.pitch_mm:g}: "
                f"a ball cannot be as large as its pitch circle; check the two figures (the pitch "
                f"is about the mean of bore and outside diameter)"
            )
        if self.balls * self.ball_mm >= math.pi * self.pitch_mm:
            raise ValueError(
                f"bearing {self.name!r}: {self.balls} balls of {self.ball_mm:g} mm do not fit "
                f"around a {self.pitch_mm:g} mm pitch circle (circumference "
                f"{math.pi * self.pitch_mm:.1f} mm); check balls, ball_mm and pitch_mm"
            )
        return self

    @property
    def _ratio(self) -> float:
        return self.ball_mm / self.pitch_mm * math.cos(math.radians(self.contact_angle_deg))

    @property
    def bpfo(self) -> float:
        """Ball pass frequency, outer race, per shaft revolution."""
        return self.balls / 2 * (1 - self._ratio)

    @property
    def bpfi(self) -> float:
        """Ball pass frequency, inner race, per shaft revolution."""
        return self.balls / 2 * (1 + self._ratio)

    @property
    def bsf(self) -> float:
        """Ball spin frequency per shaft revolution."""
        return self.pitch_mm / (2 * self.ball_mm) * (1 - self._ratio**2)

    @property
    def ftf(self) -> float:
        """Fundamental train (cage) frequency per shaft revolution."""
        return 0.5 * (1 - self._ratio)


class OperatingPoint(_Model):
    """One speed a machine was run at: % of rated and the shaft speed read there, with source."""

    percent: Number = Field(gt=0, le=200, description="Operating point, % of rated speed.")
    shaft_rpm: Number = Field(gt=0, description="Shaft speed at that point, rpm.")
    source: str = Field(default="", description="Where the shaft speed comes from.")


class MachineSpec(_Model):
    """A machine: speed, motor, bearings and the zone table that grades it (module docstring)."""

    name: str = Field(min_length=1, description="The machine's name in the data ('Motor-2').")
    description: str = Field(default="", description="One line saying what it is.")
    shaft_rpm: Number = Field(gt=0, description="Running speed of the recordings, rpm.")
    speed_percent: Number | None = Field(
        default=None, gt=0, le=200, description="That operating point, % of rated speed."
    )
    rated_rpm: Number | None = Field(default=None, gt=0, description="Rated speed, rpm.")
    poles: Count | None = Field(default=None, ge=2, description="Motor poles (2, 4, ...).")
    power_kw: Number | None = Field(default=None, gt=0, description="Rated power, kW.")
    bearings: tuple[BearingSpec, ...] = Field(default=(), description="Its rolling bearings.")
    operating_points: tuple[OperatingPoint, ...] = Field(
        default=(),
        description="Other speeds it was run at (variable speed): % of rated and shaft rpm.",
    )
    zone_table: str | None = Field(
        default=None,
        min_length=1,
        description="ISO zone table grading it: a built-in name, FILE.toml or FILE.toml#NAME.",
    )
    zone_why: str = Field(default="", description="Why that table grades this machine.")
    source: str = Field(default="", description="Where the speed and motor figures come from.")
    origin: str = Field(default="", description="Where this spec was read (set by the loader).")

    @field_validator("poles")
    @classmethod
    def _even(cls, value: int | None) -> int | None:
        if value is not None and value % 2:
            raise ValueError(f"a motor has an even number of poles, got {value}")
        return value

    @model_validator(mode="after")
    def _one_fault_one_bearing(self) -> MachineSpec:
        seen: dict[str, str] = {}
        for bearing in self.bearings:
            for fault in bearing.faults:
                if fault in seen:
                    raise ValueError(
                        f"condition {fault!r} is a fault of bearings {seen[fault]!r} and "
                        f"{bearing.name!r}; name each condition under one bearing"
                    )
                seen[fault] = bearing.name
        return self

    @property
    def shaft_hz(self) -> float:
        """Nominal running speed, Hz."""
        return self.shaft_rpm / 60.0

    def speed_at(self, percent: float) -> OperatingPoint | None:
        """The shaft speed at ``percent`` of rated speed: the listed point (or this spec's own
        ``speed_percent``); else, where ``rated_rpm`` is known, the rated speed scaled by the
        percentage, its source saying so (a drive's percentage need not scale the slip); else
        None."""
        for point in self.operating_points:
            if math.isclose(point.percent, percent):
                return point
        if self.speed_percent is not None and math.isclose(self.speed_percent, percent):
            return OperatingPoint(percent=percent, shaft_rpm=self.shaft_rpm, source=self.source)
        if self.rated_rpm is None:
            return None
        return OperatingPoint(
            percent=percent,
            shaft_rpm=self.rated_rpm * percent / 100.0,
            source=f"rated speed {self.rated_rpm:g} rpm x {percent:g} %: no source gives the "
            "speed at this point, so the slip is taken to scale with it",
        )

    def bearing_for(self, condition: str) -> BearingSpec | None:
        """The bearing whose fault ``condition`` is, or None."""
        return next((b for b in self.bearings if condition in b.faults), None)
