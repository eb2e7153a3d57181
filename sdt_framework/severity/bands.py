"""The band each sensor's V_RMS really covers: the zone table's band clipped to its chain.

The V_RMS feature sums 10-1000 Hz, but a chain passes only up to its
bandwidth (its lowest mechanical, analog or digital corner, or its Nyquist
frequency: :func:`.spectra.chain_bandwidth`, the chain's own rule); the
LIS3DH in high-resolution mode at 1344 Hz passes up to 149 Hz. Its V_RMS is
then a 10-149 Hz value, and its zones grade only what lies below 149 Hz: the
label says so and a warning names both bands. The feature values are not
changed (the paper's Table 4 stands).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping

import numpy as np
import pandas as pd

from ..errors import SDTError
from .spectra import chain_bandwidth
from .tables import V_RMS_BAND_HZ

__all__ = ["band_label", "sensor_bandwidths", "vrms_bands"]


def sensor_bandwidths(
    names: Iterable[str], sensor: Callable[[str], object]
) -> dict[str, float | None]:
    """Each sensor's chain bandwidth (:func:`.chain_bandwidth`), None where ``sensor(name)``
    (a registry's lookup, handed down) does not know it."""
    out: dict[str, float | None] = {}
    for name in names:
        try:
            out[name] = chain_bandwidth(sensor(name))
        except SDTError:
            out[name] = None
    return out


def band_label(low: float, high: float) -> str:
    """A band as the tables print it: "10-1000 Hz"."""
    return f"{low:g}-{high:.4g} Hz"


def vrms_bands(
    bandwidths: Mapping[str, float | None] | None, band: tuple[float, float] = V_RMS_BAND_HZ
) -> tuple[pd.DataFrame, list[str]]:
    """Per sensor, the band its V_RMS covers, and one warning per sensor whose chain clips it.

    ``bandwidths`` maps each sensor to its chain's bandwidth in Hz (None: not
    known, e.g. a profile this registry does not hold; the band is then not
    checked, and a warning says so). Columns: sensor, low_hz, high_hz (the
    band covered), bandwidth_hz, clipped, label.
    """
    low, high = (float(v) for v in band)
    rows, warnings = [], []
    for sensor, width in (bandwidths or {}).items():
        covered = high if width is None else min(high, float(width))
        clipped = covered < high
        rows.append(
            {
                "sensor": sensor,
                "low_hz": low,
                "high_hz": covered,
                "bandwidth_hz": np.nan if width is None else float(width),
                "clipped": clipped,
                "label": band_label(low, covered)
                + (" (clipped)" if clipped else " (not checked)" if width is None else ""),
            }
        )
        if width is None:
            warnings.append(
                f"{sensor}: its chain is not known here, so whether its V_RMS covers "
                f"{band_label(low, high)} is not checked"
            )
        elif clipped:
            warnings.append(
                f"{sensor}: V_RMS covers {band_label(low, covered)}, not the zone tables' "
                f"{band_label(low, high)}: its chain passes up to {width:.4g} Hz (its lowest "
                f"cut-off or Nyquist frequency), so its zones grade what lies below "
                f"{covered:.4g} Hz only"
            )
    columns = ["sensor", "low_hz", "high_hz", "bandwidth_hz", "clipped", "label"]
    return pd.DataFrame(rows, columns=columns), warnings
