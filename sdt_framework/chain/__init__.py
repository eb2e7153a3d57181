"""The Sensor Digital Twin measurement chain (SPEC section 2).

The chain only: it draws nothing and reads no files. Checking it against
zero motion (noise, Allan deviation) is :mod:`sdt_framework.validation`; the
signal files of ``sdt degrade`` are read in :mod:`sdt_framework.cli.signal_io`.

Public API
----------
degrade(x, fs, sensor, seed=0, *, noise=True, label="", first_index=0, ...)
    What a sensor would have recorded of a 1-D signal or a 2-D batch.
compile_chain(sensor, fs), build_stages(sensor, fs), Chain
    The chain as an ordered tuple of stages, cached per (profile, rate).
LowPass, Sample, WhiteNoise, Quantise, Stage, RunContext, SameRate
    The stages, each usable on its own, the protocol a new stage follows, and
    the mixin of a stage that keeps its input's rate.
ChainInputError, ChainInputTypeError
    The one-line error for a recording or rate the chain cannot take (the second
    one, for samples that are not real numbers, is also a TypeError).
band_fate(sensor, fs, band), chain_gain(sensor, fs, freqs), BandFate
    Whether content in a band reaches the output passed, attenuated or aliased
    (folded below the output Nyquist), and the gain line by line.
passband(sensor, fs), Passband
    The top of the band the chain passes (its lowest corner or Nyquist) and what
    sets it, so that every band a figure or check measures stays inside it.
simulation_problem(sensor, fs)
    Why a recording at fs Hz is too slow to simulate a sensor (None if it is not).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..lazy import lazy_exports

if TYPE_CHECKING:
    from .bandwidth import Passband, passband
    from .chain import Chain, build_stages, compile_chain, degrade
    from .checks import ChainInputError, ChainInputTypeError
    from .filters import design_lowpass, is_skipped, lowpass_gain
    from .response import BandFate, band_fate, chain_gain
    from .simulable import simulation_problem
    from .stages import (
        LowPass,
        Quantise,
        RunContext,
        SameRate,
        Sample,
        Stage,
        WhiteNoise,
        sample_grid,
    )

#: public name -> the submodule that defines it, loaded on first use (PEP 562): a plugin
#: that only subclasses ``SameRate`` does not load scipy.signal (0.5 s at every start)
_WHERE = {
    "Chain": "chain",
    "build_stages": "chain",
    "compile_chain": "chain",
    "degrade": "chain",
    "ChainInputError": "checks",
    "ChainInputTypeError": "checks",
    "design_lowpass": "filters",
    "is_skipped": "filters",
    "lowpass_gain": "filters",
    "simulation_problem": "simulable",
    "Passband": "bandwidth",
    "passband": "bandwidth",
    "BandFate": "response",
    "band_fate": "response",
    "chain_gain": "response",
    "LowPass": "stages",
    "Quantise": "stages",
    "RunContext": "stages",
    "SameRate": "stages",
    "Sample": "stages",
    "Stage": "stages",
    "WhiteNoise": "stages",
    "sample_grid": "stages",
}

__all__ = [
    "BandFate",
    "Chain",
    "ChainInputError",
    "ChainInputTypeError",
    "LowPass",
    "Passband",
    "Quantise",
    "RunContext",
    "SameRate",
    "Sample",
    "Stage",
    "WhiteNoise",
    "band_fate",
    "build_stages",
    "chain_gain",
    "compile_chain",
    "degrade",
    "design_lowpass",
    "is_skipped",
    "lowpass_gain",
    "passband",
    "sample_grid",
    "simulation_problem",
]

__getattr__, __dir__ = lazy_exports(__name__, _WHERE, globals())
