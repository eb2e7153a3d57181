"""The unit-to-unit spread of Macro F1 beside the spread across noise realisations.

With ``sdt benchmark --units N`` every sensor is benchmarked as N physical
units drawn from its tolerances, each with R noise repetitions. Per (scenario,
sensor, classifier), Macro F1 is first averaged over machines; then the spread
across units is the SD of the units' means over repetitions, and the spread
across noise realisations is the root-mean-square of each unit's SD over its
repetitions (both sample SDs, ddof=1). A sensor without tolerances has
identical units: its unit spread is 0 by construction.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from .document import Block, Heading, Paragraph, Table, literal
from .load import ResultsFolder

__all__ = ["unit_blocks", "unit_spread"]


def unit_spread(results: pd.DataFrame) -> pd.DataFrame:
    """One row per (scenario, sensor, classifier): units, repeats, mean, the two SDs."""
    ok = results[(results["status"] == "ok") & (results["unit"] >= 0)]
    keys = ["scenario", "sensor", "classifier"]
    per_run = ok.groupby([*keys, "unit", "repeat"], sort=True)["macro_f1"].mean()
    rows = []
    for key, part in per_run.groupby(level=keys, sort=True):
        table = part.droplevel(keys).unstack("repeat")
        unit_means = table.mean(axis=1)
        noise_sd = table.std(axis=1, ddof=1) if table.shape[1] > 1 else table.iloc[:, 0] * np.nan
        rows.append(
            {
                **dict(zip(keys, key, strict=True)),
                "units": int(table.shape[0]),
                "repeats": int(table.shape[1]),
                "mean": float(unit_means.mean()),
                "sd_units": float(unit_means.std(ddof=1)) if len(unit_means) > 1 else np.nan,
                "sd_noise": float(np.sqrt(np.mean(noise_sd**2))),
            }
        )
    return pd.DataFrame(rows)


def _f(value: float) -> str:
    return "n/a" if np.isnan(value) else f"{value:.3f}"


def unit_blocks(folder: ResultsFolder) -> list[Block]:
    """The section, or nothing for a benchmark run without ``--units``."""
    results = folder.results
    if "unit" not in results or not (results["unit"] >= 0).any():
        return []
    spread = unit_spread(results)
    rows = tuple(
        (
            literal(r.scenario),
            literal(r.sensor),
            literal(r.classifier),
            str(r.units),
            str(r.repeats),
            _f(r.mean),
            _f(r.sd_units),
            _f(r.sd_noise),
        )
        for r in spread.itertuples()
    )
    return [
        Heading("Unit-to-unit spread", 2),
        Paragraph(
            "Macro F1 of N physical units per sensor drawn from the profiles' tolerances "
            "(machines averaged): SD across units (of each unit's mean over repetitions) "
            "beside SD across noise realisations (within a unit, RMS over units)."
        ),
        Table(
            (
                "scenario",
                "sensor",
                "classifier",
                "units",
                "repeats",
                "mean F1",
                "SD across units",
                "SD across noise",
            ),
            rows,
        ),
    ]
