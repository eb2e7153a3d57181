"""``parts.search``: the profiles and parts a filter keeps, and the modes that pass.

On the sensor catalogue (its parts' figures are datasheet values); each named
mode is checked by resolving it again, so a part is kept for the right modes,
not only kept.
"""

from __future__ import annotations

import pytest

from sdt_framework import SDTError
from sdt_framework.chain import simulation_problem
from sdt_framework.parts import PartFilter, PriceLimit, resolve, search, split_name

pytestmark = pytest.mark.catalog


def _kept(registry, where: PartFilter) -> dict[str, tuple[str, ...] | None]:
    found = search(registry.sensors(), registry.parts(), where)
    return {m.part.name: m.modes for m in found.parts}


def _sensor(registry, name: str):
    """The sensor of a canonical part name in a mode, ``kx134[lpf=odr9,odr=25600,...]``."""
    base, modes = split_name(name)
    return resolve(registry.part(base), modes).sensor


def test_a_part_is_kept_for_the_modes_that_pass_and_only_those(registry):
    kept = _kept(registry, PartFilter(min_rate_hz=20000))
    assert {"adxl1002", "iim42352", "iis3dwb", "kx134"} <= set(kept)
    assert not {"adxl355", "mpu6050", "adxl345-ds"} & set(kept)  # 4 / 8 / 3.2 kHz at most
    kx134 = kept["kx134"]
    assert all(float(_sensor(registry, n).sampling_rate_hz) >= 20000 for n in kx134)
    slower = _kept(registry, PartFilter(min_rate_hz=1))["kx134"]  # every mode of the part
    assert len(slower) > len(kx134)  # and the ones left out are slower
    assert all(
        float(_sensor(registry, n).sampling_rate_hz) < 20000 for n in set(slower) - set(kx134)
    )


def test_noise_is_read_on_the_x_axis_of_each_mode(registry):
    kept = _kept(registry, PartFilter(max_noise_ug_rthz=30))
    assert set(kept) == {"adxl1002", "adxl355"}  # 25 and 22.5 ug/sqrt(Hz) (datasheets)
    assert all(_sensor(registry, n).noise_density_ug_rthz <= 30 for n in kept["adxl355"])
    found = search(registry.sensors(), [], PartFilter(max_noise_ug_rthz=30))
    assert all(s.noise_density_ug_rthz <= 30 for s in found.profiles)
    assert "adxl345" not in {s.name for s in found.profiles}  # 290 ug/sqrt(Hz), paper Table 1


def test_simulable_at_follows_the_chain_rule(registry):
    at_12k = _kept(registry, PartFilter(simulable_at_hz=12000))
    assert "iis3dwb" not in at_12k  # it samples at 26.667 kHz
    assert "iis3dwb" in _kept(registry, PartFilter(simulable_at_hz=51200))
    for name in at_12k["adxl355"]:
        assert simulation_problem(_sensor(registry, name), 12000) is None


def test_a_price_limit_keeps_priced_parts_and_no_profile(registry):
    found = search(registry.sensors(), registry.parts(), PartFilter(PriceLimit(5, "EUR")))
    assert found.profiles == ()  # profiles have no price
    assert {m.part.name for m in found.parts} == {"adxl345-ds"}  # 3.92 EUR
    assert _kept(registry, PartFilter(PriceLimit(100, "USD"))) == {}  # the prices are in EUR
    assert PriceLimit(3.92, "EUR").admits(registry.part("adxl345-ds").price)  # at the limit
    assert not PriceLimit(1000).admits(None)  # no known price


def test_a_limit_without_currency_over_several_currencies_is_refused(registry):
    parts = registry.parts()
    priced = next(p for p in parts if p.price)
    in_usd = priced.model_copy(
        update={"price": priced.price.model_copy(update={"currency": "USD"})}
    )
    with pytest.raises(SDTError, match=r"^price limit 15 has no currency .* EUR, USD; add"):
        search([], [*parts, in_usd], PartFilter(PriceLimit(15)))
    kept = search([], [*parts, in_usd], PartFilter(PriceLimit(1e6, "USD"))).parts
    assert [m.part.price.currency for m in kept] == ["USD"]


def test_no_criterion_keeps_everything_and_checks_no_mode(registry):
    where = PartFilter()
    assert not where.any
    found = search(registry.sensors(), registry.parts(), where)
    assert len(found.profiles) == len(registry.sensors())
    assert [m.part.name for m in found.parts] == [p.name for p in registry.parts()]
    assert all(m.modes is None for m in found.parts)
