"""The Allan part of ``sdt validate-noise``: read-off values beside the configured ones.

The SDT's zero-motion output of a :class:`~sdt_framework.chain.noise_check.NoiseCheck`
(all its windows, one record) and the recording, whole, each get a curve
(:mod:`sdt_framework.chain.allan`); the profile's noise terms are the
configured column.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..specs import SensorSpec
from ..units import G_N
from .allan import (
    FLOOR_FACTOR,
    ROOT_HOUR,
    AllanCurve,
    allan_curve,
    gauss_markov_adev,
    white_values,
)
from .noise_check import NoiseCheck

__all__ = ["AllanCheck", "Configured", "allan_check", "configured_terms"]


@dataclass(frozen=True)
class Configured:
    """A profile's white density (one-sided, g/sqrt(Hz)) and B (g); None where it has none."""

    nsd_g: float | None
    b_g: float | None
    terms: tuple[str, ...]

    @property
    def n_g(self) -> float | None:
        """N = sigma(1 s) = NSD / sqrt(2), g sqrt(s)."""
        return None if self.nsd_g is None else self.nsd_g / math.sqrt(2.0)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready, in ug; absent terms are None."""
        out = white_values(self.n_g) if self.n_g is not None else dict.fromkeys(white_values(0.0))
        b = None if self.b_g is None else self.b_g * 1e6
        return {**out, "bias_instability_ug": b, "terms": list(self.terms)}


def _params(use: Any) -> dict[str, Any]:
    """A stage's parameters with its model's defaults (as given if it is not bound)."""
    if use.spec is None:
        return dict(use.params)
    return use.spec.params.model_validate(use.params).model_dump()


def configured_terms(sensor: SensorSpec) -> Configured:
    """White noise and bias instability a profile configures (one axis: ``for_axis`` first).

    White terms add in power: the profile's NSD when it injects noise, each
    ``white-noise`` stage's density and each ``vrw`` stage (NSD = sqrt(2) N).
    Bias instability: the highest point of the summed ADEV^2 of the ``flicker``
    (flat, 0.664 B) and ``gauss-markov`` (closed form) stages, / 0.664: B itself
    for flicker alone, 0.931 sigma for one Gauss-Markov term. Other stages do
    not count.
    """
    white2, flat2, markov, terms = 0.0, 0.0, [], []
    if sensor.inject_noise and sensor.noise_density_ug_rthz > 0:
        white2 += (sensor.noise_density_ug_rthz * 1e-6) ** 2
        terms.append(f"noise_density_ug_rthz = {sensor.noise_density_ug_rthz:g}")
    for i, use in enumerate(sensor.stages):
        p = _params(use)
        if use.name == "white-noise":
            white2 += (p["density_ug_rthz"] * 1e-6) ** 2
        elif use.name == "vrw":
            white2 += 2.0 * (p["vrw_mps_rthr"] / ROOT_HOUR / G_N) ** 2
        elif use.name == "flicker":
            flat2 += (FLOOR_FACTOR * p["bias_instability_ug"] * 1e-6) ** 2
        elif use.name == "gauss-markov":
            markov.append((p["sigma_ug"] * 1e-6, p["tau_s"]))
        else:
            continue
        terms.append(f"{use.name}.{i}: " + ", ".join(f"{k} = {v:g}" for k, v in p.items()))
    b = None
    if markov:  # each term's hump lies within 3 decades of its correlation time
        times = [t for _, t in markov]
        grid = np.logspace(math.log10(min(times)) - 3, math.log10(max(times)) + 3, 1201)
        total = flat2 + sum(gauss_markov_adev(grid, s, t) ** 2 for s, t in markov)
        b = float(np.sqrt(np.max(total))) / FLOOR_FACTOR
    elif flat2:
        b = math.sqrt(flat2) / FLOOR_FACTOR
    return Configured(math.sqrt(white2) if white2 else None, b, tuple(terms))


@dataclass(frozen=True)
class AllanCheck:
    """Configured terms and the curves of the SDT output and, if given, the recording."""

    sensor: str
    configured: Configured
    sdt: AllanCurve
    recording: AllanCurve | None = None

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: ``configured``, ``sdt`` and ``recording`` (ug, s; None for absent)."""
        out: dict[str, Any] = {
            "floor_factor": FLOOR_FACTOR,
            "configured": self.configured.to_dict(),
            "sdt": self.sdt.to_dict(),
        }
        if self.recording is not None:
            out["recording"] = self.recording.to_dict()
        return out


def allan_check(check: NoiseCheck, sensor: SensorSpec) -> AllanCheck:
    """Allan curves of ``check``'s SDT output and recording, beside ``sensor``'s terms.

    ``sensor`` is the profile the check ran (the same axis).
    """
    recording = None
    if check.recording_signal is not None and check.recording_fs is not None:
        recording = allan_curve(check.recording_signal, check.recording_fs, "recording")
    return AllanCheck(
        check.sensor,
        configured_terms(sensor),
        allan_curve(check.sdt_signal, check.sdt_fs, "SDT " + check.sensor),
        recording,
    )
