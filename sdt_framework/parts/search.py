"""Which sensor profiles and parts pass a search: price, rate, noise, simulable from a recording.

``sdt sensors list --max-price --min-rate --max-noise --simulable-at`` is
:func:`search` with a :class:`PartFilter`. A part passes when at least one of
its modes does (``min_rate_hz=6400``: some mode samples at 6400 Hz or faster),
and the modes that pass are named; noise is read on the X axis, the
benchmark's default. Profiles have no price, so a price limit leaves every
profile out. A price limit without a currency is refused when the parts'
prices are in more than one (10 of what?).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, fields

from ..errors import SDTError
from ..specs import SensorSpec
from .model import PartSpec, Price
from .resolve import all_modes, resolve

__all__ = ["PartFilter", "PartMatch", "PriceLimit", "SearchResult", "search"]


@dataclass(frozen=True)
class PriceLimit:
    """At most ``amount``, in ``currency`` (None: the one currency every price is in)."""

    amount: float
    currency: str | None = None

    def admits(self, price: Price | None) -> bool:
        """Whether ``price`` is known, in this currency (if named) and at most the amount."""
        if price is None:
            return False
        same = self.currency is None or price.currency == self.currency
        return same and price.amount <= self.amount


@dataclass(frozen=True)
class PartFilter:
    """What a profile or a part's mode must meet; None leaves that criterion out."""

    max_price: PriceLimit | None = None
    min_rate_hz: float | None = None
    max_noise_ug_rthz: float | None = None
    #: the rate of a recording the sensor must be simulable from (``chain.simulation_problem``)
    simulable_at_hz: float | None = None

    @property
    def any(self) -> bool:
        """True if any criterion is set."""
        return any(getattr(self, f.name) is not None for f in fields(self))

    def admits(self, sensor: SensorSpec) -> bool:
        """Whether a sensor (a profile, or a part in a mode) meets rate, noise and simulability."""
        rate, noise = sensor.sampling_rate_hz, sensor.noise_density_ug_rthz
        if self.min_rate_hz is not None and rate != "native" and float(rate) < self.min_rate_hz:
            return False
        if self.max_noise_ug_rthz is not None and noise > self.max_noise_ug_rthz:
            return False
        if self.simulable_at_hz is None:
            return True
        # here, not at the top: only this criterion needs the chain package
        from ..chain.simulable import simulation_problem

        return simulation_problem(sensor, self.simulable_at_hz) is None


@dataclass(frozen=True)
class PartMatch:
    """A part that passed, and the canonical names of its modes that did."""

    part: PartSpec
    #: None when no criterion was set (every part passes; no mode was checked)
    modes: tuple[str, ...] | None


@dataclass(frozen=True)
class SearchResult:
    """The profiles and the parts that passed, in the order given."""

    profiles: tuple[SensorSpec, ...]
    parts: tuple[PartMatch, ...]


def _currencies(parts: list[PartSpec], limit: PriceLimit | None) -> None:
    """Refuse a limit without a currency when the prices are in several."""
    if limit is None or limit.currency is not None:
        return
    found = sorted({p.price.currency for p in parts if p.price})
    if len(found) > 1:
        raise SDTError(
            f"price limit {limit.amount:g} has no currency and the prices are in "
            f"{', '.join(found)}; add the currency, e.g. {limit.amount:g}{found[0]}"
        )


def _modes(part: PartSpec, where: PartFilter) -> tuple[str, ...]:
    if where.max_price is not None and not where.max_price.admits(part.price):
        return ()
    sensors = (resolve(part, mode).sensor for mode in all_modes(part))
    return tuple(s.name for s in sensors if where.admits(s))


def search(
    profiles: Iterable[SensorSpec], parts: Iterable[PartSpec], where: PartFilter
) -> SearchResult:
    """The profiles and parts that pass ``where`` (a part: one of its modes passes).

    Raises
    ------
    SDTError
        A price limit without a currency while the parts' prices are in several.
    """
    parts = list(parts)
    _currencies(parts, where.max_price)
    kept = [s for s in profiles if where.max_price is None and where.admits(s)]
    if not where.any:
        return SearchResult(tuple(kept), tuple(PartMatch(p, None) for p in parts))
    matches = [PartMatch(p, _modes(p, where)) for p in parts]
    return SearchResult(tuple(kept), tuple(m for m in matches if m.modes))
