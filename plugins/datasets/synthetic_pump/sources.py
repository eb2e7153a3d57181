"""The sources of one acquisition of the synthetic pump, shared by every channel.

What the rig does, drawn once per acquisition: the shaft-synchronous lines (the
healthy baseline and a fault's own, as complex exponentials of the shaft angle:
orders of the running speed), bearing impacts at their defect rate and
shaft-locked knocks (impulse trains by index arithmetic), suction cavitation
bursts at vane passes, the throttled valve's hiss and recirculation, and the
flow noise. Every rate is an order of the acquisition's shaft speed, so the
lines move with the machine's speed; the casing resonances that ring them are
the channels' (``model.CHANNELS``), in Hz. ``generate.py`` passes them through
each channel's path and mixes each column (``mix.py``).
"""

from __future__ import annotations

from functools import cache

import numpy as np
from scipy import signal

from sdt_framework.seeding import rng

from . import faults as f
from . import mix
from . import model as m

__all__ = ["clipped_normal", "resonator", "sources"]


def clipped_normal(gen: np.random.Generator, sd: float, limit: float, size: int | None = None):
    return np.clip(gen.normal(0.0, sd, size), -limit * sd, limit * sd)


@cache
def resonator(freq: float, zeta: float, fs: float) -> tuple[np.ndarray, np.ndarray, float]:
    """Band-pass resonance (impulse response peak 1) and its white-noise RMS gain.

    Zeros at DC and Nyquist: a structure's acceleration response to a force
    vanishes at low frequency, so flow noise and impacts add nothing below the
    shaft-synchronous band.
    """
    omega = 2 * np.pi * freq / fs
    r = np.exp(-zeta * omega)
    a = np.array([1.0, -2 * r * np.cos(omega), r * r])
    impulse = np.zeros(int(12 / (zeta * omega)))
    impulse[0] = 1.0
    h = signal.lfilter([1.0, 0.0, -1.0], a, impulse)
    b = np.array([1.0, 0.0, -1.0]) / np.abs(h).max()
    return b, a, float(np.sqrt(np.sum((h / np.abs(h).max()) ** 2)))


@cache
def _band(band: tuple[float, float], fs: float) -> np.ndarray:
    return signal.butter(4, band, btype="bandpass", fs=fs, output="sos")


def _impulses(n: int, fs: float, times: np.ndarray, amplitudes: np.ndarray) -> np.ndarray:
    """An impulse train: ``amplitudes`` placed at the samples nearest ``times``."""
    out = np.zeros(n)
    index = np.rint(times * fs).astype(np.int64)
    keep = (index >= 0) & (index < n)
    np.add.at(out, index[keep], amplitudes[keep])
    return out


def _rotation(known: dict[float, np.ndarray], order: float, angle: np.ndarray) -> np.ndarray:
    """exp(1j * order * angle); an integer order as a product of known lower ones (cheaper)."""
    if order == 1 or not float(order).is_integer():
        return np.exp(1j * order * angle)
    if 1.0 not in known:
        known[1.0] = np.exp(1j * angle)
    lower = max(k for k in known if k < order and float(k).is_integer())
    rest = order - lower
    factor = known[rest] if rest in known else _rotation(known, rest, angle)
    return known[lower] * factor


def _harmonics(machine: m.Machine, condition: str, level: int, seed: int, scatter: dict):
    """Shaft-synchronous components of a run: (baseline, fault), each {(group, order): amp}.

    The baseline is the healthy machine's vibration, whose response at each sensor
    varies from run to run (installation); the fault adds a component at a phase
    fixed per machine and component (the added unbalance mass always at the same angle).
    """
    parts: tuple[dict, dict] = ({}, {})
    hydraulic = scatter["hydraulic"]  # vane-pass pulsation follows the operating point
    scale = machine.line_scale  # the lines' forces at this speed (speeds.toml, [lines])
    table = [
        (0, g, k, a * (hydraulic if k % m.VANES == 0 else 1.0) * scale, "base")
        for g, k, a in m.BASELINE
    ]
    step = f.SEVERITY_STEPS.get(condition, range(1, level + 1))[level - 1]
    table += [
        (1, g, k, a * step * scale, condition) for g, k, a in f.FAULT_HARMONICS.get(condition, ())
    ]
    for part, group, order, amp, tag in table:
        # the rotor's angle: the same at every speed (the mass is where it was put)
        phase = rng(seed, machine.name, "phase", group, order, tag).uniform(0, 2 * np.pi)
        key = (group, float(order))
        terms = parts[part]
        terms[key] = terms.get(key, 0j) + amp * scatter[group] * np.exp(1j * phase)
    return parts


def sources(
    machine: m.Machine,
    condition: str,
    level: int,
    run: str,
    acq: int,
    n: int,
    seed: int,
    fs: float,
    point: float,
) -> dict:
    """Everything shared by the channels of one acquisition (``point``: operating point)."""
    run_gen = rng(seed, machine.draws, run, "run")
    speed = 1 + clipped_normal(run_gen, m.SPEED_JITTER, 3)
    groups = ("motor_radial", "motor_axial", "pump_radial", "pump_axial", "impacts", "cavitation")
    scatter = dict(
        zip(groups, np.exp(clipped_normal(run_gen, m.AMPLITUDE_SCATTER, 2, 6)), strict=True)
    )
    scatter["hydraulic"] = point**m.VANE_PASS_EXPONENT
    gen = rng(seed, machine.draws, run, "acquisition", acq)
    f1 = machine.shaft_hz * speed * (1 + clipped_normal(gen, 5e-4, 3))
    theta = gen.uniform(0, 2 * np.pi)  # shaft angle at the first sample
    t = np.arange(n) / fs
    drift = np.exp(clipped_normal(gen, m.ACQUISITION_DRIFT, 3, 2))  # (low, broadband)
    rotation: dict[float, np.ndarray] = {}
    lowfreq: tuple[dict[str, np.ndarray], dict[str, np.ndarray]] = ({}, {})
    for part, terms in enumerate(_harmonics(machine, condition, level, seed, scatter)):
        for (group, order), amp in terms.items():
            if order not in rotation:
                rotation[order] = _rotation(rotation, order, 2 * np.pi * f1 * t + theta)
            gain = drift[0] if part == 0 else 1.0
            lowfreq[part][group] = lowfreq[part].get(group, 0) + gain * amp * rotation[order]
    impacts = {"motor_bearing": np.zeros(n), "pump_bearing": np.zeros(n), "coupling": np.zeros(n)}
    if condition in f.IMPACTS:
        where, bearing, race, amp = f.IMPACTS[condition]
        size = f.IMPACT_STEPS.get(condition, range(1, level + 1))[level - 1]
        if bearing is None:  # a knock locked to the shaft: a fixed number per revolution
            rate, slip, scatter_sd = f1 * float(race), 0.0, f.KNOCK_SCATTER
        else:
            rate = f1 * (bearing.bpfo if race == "outer" else bearing.bpfi)
            slip, scatter_sd = f.BEARING_SLIP, 0.0
        count = int(n / fs * rate) + 2
        steps = (1 + clipped_normal(gen, slip, 3, count)) / rate
        times = gen.uniform(0, 1 / rate) + np.cumsum(steps) - steps[0]
        amps = amp * size * scatter["impacts"] * (1 + clipped_normal(gen, scatter_sd, 3, count))
        if race == "inner":  # the defect passes through the load zone once per revolution
            amps *= 0.3 + 0.7 * (1 + np.cos(2 * np.pi * f1 * times + theta)) / 2
        impacts[where] = _impulses(n, fs, times, amps)
    cavitation, hiss_wave = np.zeros(n), np.zeros(n)
    if condition in f.CAVITATION:
        amplitudes, rates = f.CAVITATION[condition]
        amp = amplitudes[level - 1] * scatter["cavitation"]
        vpf = m.VANES * f1
        # bursts collapse as a vane passes the low-pressure zone: a random subset of vane passes
        passes = (np.arange(int(vpf * n / fs) + 1) + gen.uniform(0, 1)) / vpf
        chosen = passes[gen.random(passes.size) < rates[level - 1] / vpf]
        burst = np.exp(-np.arange(int(5 * f.CAVITATION_BURST_S * fs)) / (f.CAVITATION_BURST_S * fs))
        strength = amp * np.exp(clipped_normal(gen, 0.35, 3, chosen.size))
        envelope = signal.fftconvolve(_impulses(n, fs, chosen, strength), burst)[:n]
        envelope += f.CAVITATION_HISS * amp * (1 + np.cos(2 * np.pi * vpf * t)) / 2
        carrier = signal.sosfilt(_band(f.CAVITATION_BAND_HZ, fs), gen.standard_normal(n))
        cavitation = envelope * carrier / np.std(carrier)
    if condition in f.DISCHARGE:
        hiss, surge = f.DISCHARGE[condition]
        carrier = signal.sosfilt(_band(f.DISCHARGE_BAND_HZ, fs), gen.standard_normal(n))
        hiss_wave = hiss[level - 1] * scatter["cavitation"] * carrier / np.std(carrier)
        lo, hi = f.RECIRCULATION_ORDERS
        sos = signal.butter(2, (lo * f1, hi * f1), btype="bandpass", fs=fs, output="sos")
        wave = signal.sosfilt(sos, gen.standard_normal(n))
        wave = signal.hilbert(wave / np.std(wave)) * surge[level - 1] * scatter["pump_radial"]
        wave = wave * machine.line_scale  # a hydraulic force, as the lines
        lowfreq[1]["pump_radial"] = lowfreq[1].get("pump_radial", 0) + wave
    tone = mix.TONE_ORDER * (2 * np.pi * f1 * t + theta)
    trend = np.exp(f.FLOW_TREND.get(condition, 0.0) * level)  # hydraulic power lost
    flow = drift[1] * trend * gen.standard_normal(n)
    return {
        "lowfreq": lowfreq,
        "impacts": impacts,
        "flow": flow,
        "cavitation": cavitation,
        "hiss": hiss_wave,
        "tone": (np.sin(tone), np.cos(tone)),
    }
