"""The synthetic pump generator: the embedded default dataset (no download).

One run (a condition directory) is generated at once for all its channels:
the rig's sources (shaft harmonics, vane pass, impacts, flow noise,
cavitation) are drawn once per acquisition and every channel sees them through
its own transfer path (``synth_model.CHANNELS``), so channels are simultaneous
views of the same event. All draws come from ``seeding.rng(seed, machine,
run, ...)``: the same seed gives bit-identical signals whatever the selection
or loading order. Generation is vectorised: harmonics as complex exponentials,
impulse trains by index arithmetic filtered by two-pole resonators
(``scipy.signal.lfilter``), cavitation as band-passed noise under burst
envelopes (``fftconvolve``).
"""

from __future__ import annotations

from functools import cache

import numpy as np
from scipy import signal

from ..seeding import rng
from . import synth_model as m

__all__ = ["FS_HZ", "generate_run"]

FS_HZ = 20000.0


def _clipped_normal(gen: np.random.Generator, sd: float, limit: float, size: int | None = None):
    return np.clip(gen.normal(0.0, sd, size), -limit * sd, limit * sd)


@cache
def _resonator(freq: float, zeta: float, fs: float) -> tuple[np.ndarray, np.ndarray, float]:
    """Two-pole resonator (impulse response peak ~1) and its white-noise RMS gain."""
    omega = 2 * np.pi * freq / fs
    r = np.exp(-zeta * omega)
    b = np.array([np.sin(omega)])
    a = np.array([1.0, -2 * r * np.cos(omega), r * r])
    impulse = np.zeros(int(12 / (zeta * omega)))
    impulse[0] = 1.0
    gain = float(np.sqrt(np.sum(signal.lfilter(b, a, impulse) ** 2)))
    return b, a, gain


@cache
def _cavitation_band(fs: float) -> np.ndarray:
    return signal.butter(4, m.CAVITATION_BAND_HZ, btype="bandpass", fs=fs, output="sos")


def _impulses(n: int, fs: float, times: np.ndarray, amplitudes: np.ndarray) -> np.ndarray:
    """An impulse train: ``amplitudes`` placed at the samples nearest ``times``."""
    out = np.zeros(n)
    index = np.rint(times * fs).astype(np.int64)
    keep = (index >= 0) & (index < n)
    np.add.at(out, index[keep], amplitudes[keep])
    return out


def _harmonics(machine: m.Machine, condition: str, level: int, seed: int, scatter: dict):
    """(group, order, complex amplitude) of every shaft-synchronous component of a run."""
    terms: dict[tuple[str, float], complex] = {}
    table = [(g, k, a, "base") for g, k, a in m.BASELINE]
    table += [(g, k, a * level, condition) for g, k, a in m.FAULT_HARMONICS.get(condition, ())]
    for group, order, amp, tag in table:
        # phase fixed per machine and component: added unbalance mass always at the same angle
        phase = rng(seed, machine.name, "phase", group, order, tag).uniform(0, 2 * np.pi)
        key = (group, float(order))
        terms[key] = terms.get(key, 0j) + amp * scatter[group] * np.exp(1j * phase)
    return terms


def _sources(
    machine: m.Machine, condition: str, level: int, run: str, acq: int, n: int, seed: int, fs: float
) -> dict:
    """Everything shared by the channels of one acquisition."""
    run_gen = rng(seed, machine.name, run, "run")
    speed = 1 + _clipped_normal(run_gen, m.SPEED_JITTER, 3)
    groups = ("motor_radial", "motor_axial", "pump_radial", "pump_axial", "impacts", "cavitation")
    scatter = dict(
        zip(groups, np.exp(_clipped_normal(run_gen, m.AMPLITUDE_SCATTER, 2, 6)), strict=True)
    )
    gen = rng(seed, machine.name, run, "acquisition", acq)
    f1 = machine.shaft_hz * speed * (1 + _clipped_normal(gen, 5e-4, 3))
    theta = gen.uniform(0, 2 * np.pi)  # shaft angle at the first sample
    t = np.arange(n) / fs
    lowfreq: dict[str, np.ndarray] = {}
    rotation: dict[float, np.ndarray] = {}
    for (group, order), amp in _harmonics(machine, condition, level, seed, scatter).items():
        if order not in rotation:
            rotation[order] = np.exp(1j * order * (2 * np.pi * f1 * t + theta))
        lowfreq[group] = lowfreq.get(group, 0) + amp * rotation[order]
    impacts = {"motor_bearing": np.zeros(n), "pump_bearing": np.zeros(n), "coupling": np.zeros(n)}
    if condition in m.BEARING_FAULTS:
        where, bearing, race, amp = m.BEARING_FAULTS[condition]
        rate = f1 * (bearing.bpfo if race == "outer" else bearing.bpfi)
        count = int(n / fs * rate) + 2
        steps = (1 + _clipped_normal(gen, m.BEARING_SLIP, 3, count)) / rate
        times = gen.uniform(0, 1 / rate) + np.cumsum(steps) - steps[0]
        amps = np.full(count, amp * level * scatter["impacts"])
        if race == "inner":  # the defect passes through the load zone once per revolution
            amps *= 0.3 + 0.7 * (1 + np.cos(2 * np.pi * f1 * times + theta)) / 2
        impacts[where] = _impulses(n, fs, times, amps)
    if condition == "coupling":
        times = (np.arange(int(2 * f1 * n / fs) + 2) + gen.uniform(0, 1)) / (2 * f1)
        amps = (
            m.COUPLING_IMPACT_G
            * level
            * scatter["impacts"]
            * (1 + _clipped_normal(gen, 0.2, 3, times.size))
        )
        impacts["coupling"] = _impulses(n, fs, times, amps)
    cavitation = np.zeros(n)
    if condition in m.CAVITATION:
        amplitudes, rates = m.CAVITATION[condition]
        amp = amplitudes[level - 1] * scatter["cavitation"]
        vpf = m.VANES * f1
        # bursts collapse as a vane passes the low-pressure zone: a random subset of vane passes
        passes = (np.arange(int(vpf * n / fs) + 1) + gen.uniform(0, 1)) / vpf
        chosen = passes[gen.random(passes.size) < rates[level - 1] / vpf]
        burst = np.exp(-np.arange(int(5 * m.CAVITATION_BURST_S * fs)) / (m.CAVITATION_BURST_S * fs))
        strength = amp * np.exp(_clipped_normal(gen, 0.35, 3, chosen.size))
        envelope = signal.fftconvolve(_impulses(n, fs, chosen, strength), burst)[:n]
        envelope += m.CAVITATION_HISS * amp * (1 + np.cos(2 * np.pi * vpf * t)) / 2
        carrier = signal.sosfilt(_cavitation_band(fs), gen.standard_normal(n))
        cavitation = envelope * carrier / np.std(carrier)
    flow = gen.standard_normal(n)
    return {"lowfreq": lowfreq, "impacts": impacts, "flow": flow, "cavitation": cavitation}


def _channel(src: dict, path: m.ChannelPath, noise: np.ndarray, fs: float) -> np.ndarray:
    """One sensor's view of the sources: complex gains, resonances, direct cavitation, noise."""
    out = np.zeros(noise.size, dtype=complex)
    for group, wave in src["lowfreq"].items():
        out += path.gains[group] * wave
    result = out.real + path.cavitation * src["cavitation"] + noise
    excitation = sum(path.impacts[k] * v for k, v in src["impacts"].items())
    for freq, zeta, weight in path.modes:
        b, a, gain = _resonator(freq, zeta, fs)
        drive = excitation + src["flow"] * (m.FLOW_NOISE_G / gain)
        result += weight * signal.lfilter(b, a, drive)
    return result


def generate_run(
    machine: str,
    condition: str,
    level: int,
    *,
    channels: tuple[str, ...],
    acquisitions: int,
    duration_s: float,
    seed: int,
    fs: float = FS_HZ,
) -> dict[str, np.ndarray]:
    """Generate one run: channel -> float64 (acquisitions, round(duration_s * fs)) in g.

    Parameters
    ----------
    machine, condition, level
        e.g. ("Motor-4", "align angular", 3); for healthy, ``level`` numbers the run.
    channels
        Subset of ``ch1``..``ch5``.
    acquisitions, duration_s
        Number and length (s) of continuous acquisitions.
    seed
        Base seed; every draw derives from (seed, machine, run, ...).
    """
    spec = m.MACHINES[machine]
    run = f"{condition} {level}"
    severity = 1 if condition == "healthy" else level
    n = round(duration_s * fs)
    out = {ch: np.empty((acquisitions, n)) for ch in channels}
    for acq in range(acquisitions):
        src = _sources(spec, condition, severity, run, acq, n, seed, fs)
        for ch in channels:
            noise = rng(seed, machine, run, "noise", acq, ch).normal(0, m.SENSOR_NOISE_G, n)
            out[ch][acq] = _channel(src, m.CHANNELS[ch], noise, fs)
    return out
