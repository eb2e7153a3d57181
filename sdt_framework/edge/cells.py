"""Battery cells for a node: capacity at the node's drain, self-discharge, shelf life, sources.

Life in years for an average load current I (mA) drawn from a cell whose
capacity at that drain is C(I) (mAh) and which loses a fraction s of its
capacity per year on its own (the self-discharge acts as a second load of
C s / 8766 h):

    life = min( 1 / (I 8766 h / C(I) + s),  shelf life )   years

(8766 h = 365.25 days). C(I) is the maker's or the handbook's capacity at a
constant drain: a curve interpolated linearly in log(I) between its points and
held flat beyond its ends (the lowest drain a curve shows is far above a
node's 30-60 uA), or one rated figure where no curve was read. No cell
outlives its rated shelf life: the life is capped there and the cap is named.
Capacity is a room-temperature, constant-drain figure: cold, the radio's
current pulses and the voltage they pull down (Li-SOCl2 passivation) are not
followed, which the node's output says.

The built-in cells and every figure's source are in ``cells.toml`` beside this
module; any other cell is a :class:`Cell` with the user's own figures
(``sdt budget --capacity-mah ... --self-discharge-pct ... --shelf-life-years``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from pydantic import Field, model_validator

from ..errors import SDTError, UnknownNameError, shown
from .sourced import DataModel, Figure, read_data

__all__ = ["CELLS", "HOURS_PER_YEAR", "Cell", "Life", "cell", "cell_life", "life_years"]

#: hours in a year of 365.25 days
HOURS_PER_YEAR = 8766.0


@dataclass(frozen=True)
class Cell:
    """A battery: capacity (flat, or a curve against drain), voltage, self-discharge, shelf life.

    ``curve`` holds (drain mA, capacity mAh) points, drains rising; empty means
    ``capacity_mah`` at any drain. ``self_discharge_per_year`` is a fraction
    lost per year, ``shelf_life_years`` the life no node can exceed on it.
    """

    name: str
    capacity_mah: float
    voltage_v: float
    self_discharge_per_year: float
    shelf_life_years: float
    source: str
    self_discharge_source: str = ""
    shelf_life_source: str = ""
    curve: tuple[tuple[float, float], ...] = field(default=())

    def __post_init__(self) -> None:
        for name in ("capacity_mah", "voltage_v", "shelf_life_years"):
            value = getattr(self, name)
            if not (isinstance(value, int | float) and math.isfinite(value) and value > 0):
                raise SDTError(
                    f"battery {self.name!r}: {name} must be positive, got {shown(value)}"
                )
        rate = self.self_discharge_per_year
        if not (isinstance(rate, int | float) and math.isfinite(rate) and 0 <= rate < 1):
            raise SDTError(
                f"battery {self.name!r}: self-discharge must be a fraction per year in [0, 1), "
                f"got {shown(rate)}"
            )
        drains = [d for d, _ in self.curve]
        if self.curve and (drains != sorted(set(drains)) or min(drains) <= 0):
            raise SDTError(f"battery {self.name!r}: curve drains must be positive and rising")

    def capacity_at(self, drain_a: float) -> float:
        """Capacity in mAh at a constant drain of ``drain_a`` amperes (module notes)."""
        if not self.curve:
            return self.capacity_mah
        drains = np.log([d for d, _ in self.curve])
        capacities = [c for _, c in self.curve]
        at = math.log(max(drain_a * 1e3, 1e-12))
        return float(np.interp(at, drains, capacities))


@dataclass(frozen=True)
class Life:
    """A cell's life at a drain: the years (capped), the uncapped estimate, and the cap's words."""

    years: float
    uncapped_years: float
    capacity_mah: float
    capped: bool

    def cap_note(self, battery: Cell) -> str:
        """Why the life stops where it does, when the shelf life caps it (else ``""``)."""
        if not self.capped:
            return ""
        return (
            f"battery {battery.name}: life capped at its {battery.shelf_life_years:g}-year shelf "
            f"life (the drain alone would give {_years(self.uncapped_years)}): "
            f"{battery.shelf_life_source or 'user setting'}"
        )


def _years(value: float) -> str:
    return "no end" if math.isinf(value) else f"{value:.1f} years"


def cell_life(average_current_a: float, battery: Cell) -> Life:
    """Years until ``battery`` is empty at ``average_current_a``, capped at its shelf life."""
    if not (math.isfinite(average_current_a) and average_current_a >= 0):
        raise SDTError(f"average current must be >= 0 A, got {shown(average_current_a)}")
    capacity = battery.capacity_at(average_current_a)
    per_year = average_current_a * 1e3 * HOURS_PER_YEAR / capacity + battery.self_discharge_per_year
    uncapped = math.inf if per_year == 0 else 1.0 / per_year
    capped = uncapped > battery.shelf_life_years
    years = battery.shelf_life_years if capped else uncapped
    return Life(years, uncapped, capacity, capped)


def life_years(average_current_a: float, battery: Cell) -> float:
    """The capped life in years (:func:`cell_life`)."""
    return cell_life(average_current_a, battery).years


class _Capacity(DataModel):
    mah: float = Field(gt=0)
    rated_drain_ma: float = Field(gt=0)
    curve: list[tuple[float, float]] = Field(default_factory=list)
    curve_of: str = ""
    source: Figure


class _SelfDischarge(DataModel):
    lost_pct: float | None = Field(default=None, ge=0, lt=100)
    retained_pct: float | None = Field(default=None, gt=0, le=100)
    years: float = Field(gt=0)
    source: Figure

    @model_validator(mode="after")
    def _one(self) -> _SelfDischarge:
        if (self.lost_pct is None) == (self.retained_pct is None):
            raise ValueError("give exactly one of lost_pct or retained_pct")
        return self

    @property
    def per_year(self) -> float:
        lost = self.lost_pct if self.lost_pct is not None else 100 - self.retained_pct  # type: ignore[operator]
        return lost / 100 / self.years


class CellEntry(DataModel):
    """One ``[[cell]]`` of cells.toml."""

    name: str
    description: str
    voltage_v: float = Field(gt=0)
    capacity: _Capacity
    self_discharge: _SelfDischarge
    shelf_life: Figure


class _CellFile(DataModel):
    cell: list[CellEntry]


def _curve(entry: CellEntry, entries: dict[str, CellEntry]) -> tuple[tuple[float, float], ...]:
    """The entry's own curve, or another cell's curve scaled to this one's rating."""
    cap = entry.capacity
    if not cap.curve_of:
        return tuple((float(d), float(c)) for d, c in cap.curve)
    shape = entries[cap.curve_of.lower()]
    reference = Cell("shape", shape.capacity.mah, 1.0, 0.0, 1.0, "", curve=_curve(shape, entries))
    scale = cap.mah / reference.capacity_at(cap.rated_drain_ma / 1e3)
    return tuple((d, c * scale) for d, c in reference.curve)


def _cell(entry: CellEntry, entries: dict[str, CellEntry]) -> Cell:
    cap, sd = entry.capacity, entry.self_discharge
    curve = _curve(entry, entries)
    source = f"{entry.description}; capacity: {cap.source.cited()}"
    if cap.source.note:
        source += f" ({cap.source.note})"
    return Cell(
        entry.name,
        cap.mah,
        entry.voltage_v,
        sd.per_year,
        entry.shelf_life.value,
        source,
        f"{sd.source.cited()}: '{sd.source.printed}'",
        f"{entry.shelf_life.cited()}: '{entry.shelf_life.printed}'",
        curve,
    )


def _load() -> tuple[dict[str, CellEntry], dict[str, Cell]]:
    entries = {e.name.lower(): e for e in read_data("cells.toml", _CellFile).cell}
    return entries, {key: _cell(entry, entries) for key, entry in entries.items()}


#: the cells.toml entries (with every figure's source) and the cells built from them
CELL_ENTRIES, CELLS = _load()


def cell(name: str) -> Cell:
    """A built-in cell by name, case-insensitive (``2xAA``, ``C``, ``D``)."""
    key = str(name).strip().lower()
    if key not in CELLS:
        raise UnknownNameError("battery", str(name), [c.name for c in CELLS.values()])
    return CELLS[key]
