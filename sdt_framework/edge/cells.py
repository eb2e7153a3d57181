"""Battery cells for a node: capacity, self-discharge, each with where it comes from.

Life in years for an average load current I (mA) drawn from a cell of
capacity C (mAh) that loses a fraction s of its capacity per year on its own:
the self-discharge acts as a second load of C s / 8766 h, so

    life = C / (I + C s / 8766 h)  hours  =  1 / (I 8766 h / C + s)  years

(8766 h = 365.25 days). Capacity is what the maker rates at its own test load;
a cell delivers less at high pulse currents or in the cold, which this model
does not follow (docs/edge.md says so).

Built-in cells, as read for this catalogue:

- ``2xAA``: two Energizer L91 Ultimate Lithium (Li/FeS2) AA cells in series,
  3.0 V. 3000 mAh as quoted from the Energizer L91 datasheet by a secondary
  source (electronicshopbest.blogspot.com, 2009: "According to data sheet
  published by Energizer, the capacity of the Lithium AA cell (L91) is
  3000mAh"); self-discharge from the earlier L91 datasheet as quoted on
  candlepowerforums.com ("Shelf Life: 15 years at 21°C (90% of rated
  capacity)"), i.e. 10 % in 15 years = 0.667 %/year. Both secondary: the
  Energizer datasheet itself was not in the stored copies read.
- ``C``: Saft LS 26500, 3.6 V Li-SOCl2 C-size bobbin cell, 7.7 Ah; "low
  self-discharge rate (less than 1 % after 1 year of storage at +20 °C)":
  1 %/year used as the bound. Saft LS 26500 datasheet as carried on the
  novapart.co product page "LS26500 1S1P FLC" (battery capacity 7.7Ah).
- ``D``: Tadiran TL-5930/S, 3.6 V Li-SOCl2 D cell, 19.0 Ah, from the vendor
  listing title "TL Series Lithium D Cell 3.6 V 19.0 Ah" (futureelectronics.com,
  part tl-5930-s); its self-discharge is not in that source, so none is counted
  (the life is then an upper bound; the table says so).

Alkaline C and D cells are not built in: the Duracell MN1400 datasheet read
rates no capacity ("Delivered capacity is dependent on the applied load,
operating temperature and cut-off voltage"). Any other cell is a :class:`Cell`
with the user's own capacity and self-discharge (``--capacity-mah``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import SDTError, UnknownNameError

__all__ = ["CELLS", "HOURS_PER_YEAR", "Cell", "cell", "life_years"]

#: hours in a year of 365.25 days
HOURS_PER_YEAR = 8766.0


@dataclass(frozen=True)
class Cell:
    """A battery: capacity, voltage, self-discharge per year (None: not known), sources."""

    name: str
    capacity_mah: float
    voltage_v: float
    self_discharge_per_year: float | None
    source: str
    self_discharge_source: str = ""

    def __post_init__(self) -> None:
        for field, value in (("capacity_mah", self.capacity_mah), ("voltage_v", self.voltage_v)):
            if not (math.isfinite(value) and value > 0):
                raise SDTError(f"battery {self.name!r}: {field} must be positive, got {value!r}")
        rate = self.self_discharge_per_year
        if rate is not None and not (math.isfinite(rate) and 0 <= rate < 1):
            raise SDTError(
                f"battery {self.name!r}: self-discharge must be a fraction per year in [0, 1), "
                f"got {rate!r}"
            )


_L91 = (
    "Energizer L91 datasheet as quoted by electronicshopbest.blogspot.com (2009; secondary): "
    "'the capacity of the Lithium AA cell (L91) is 3000mAh'"
)
CELLS: dict[str, Cell] = {
    c.name.lower(): c
    for c in (
        Cell(
            "2xAA",
            3000.0,
            3.0,
            0.10 / 15.0,
            f"{_L91}; two cells in series, 3.0 V",
            "earlier L91 datasheet as quoted on candlepowerforums.com: 'Shelf Life: 15 years "
            "at 21°C (90% of rated capacity)' = 10 % in 15 years (secondary)",
        ),
        Cell(
            "C",
            7700.0,
            3.6,
            0.01,
            "Saft LS 26500 Li-SOCl2 C cell datasheet (novapart.co page 'LS26500 1S1P FLC'): "
            "3.6 V, 7.7 Ah",
            "same datasheet: 'less than 1 % after 1 year of storage at + 20°C' (bound used)",
        ),
        Cell(
            "D",
            19000.0,
            3.6,
            None,
            "Tadiran TL-5930/S Li-SOCl2 D cell, vendor listing 'TL Series Lithium D Cell "
            "3.6 V 19.0 Ah' (futureelectronics.com)",
            "",
        ),
    )
}


def cell(name: str) -> Cell:
    """A built-in cell by name, case-insensitive (``2xAA``, ``C``, ``D``)."""
    key = str(name).strip().lower()
    if key not in CELLS:
        raise UnknownNameError("battery", str(name), [c.name for c in CELLS.values()])
    return CELLS[key]


def life_years(average_current_a: float, battery: Cell) -> float:
    """Years until ``battery`` is empty at ``average_current_a`` (see the module formula)."""
    if not (math.isfinite(average_current_a) and average_current_a >= 0):
        raise SDTError(f"average current must be >= 0 A, got {average_current_a!r}")
    rate = battery.self_discharge_per_year or 0.0
    per_year = average_current_a * 1e3 * HOURS_PER_YEAR / battery.capacity_mah + rate
    return math.inf if per_year == 0 else 1.0 / per_year
