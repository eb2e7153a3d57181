"""The synthetic pump generator: the embedded default dataset (no download).

One run (a condition directory) is generated at once for all its channels:
the rig's sources (shaft harmonics, vane pass, impacts, flow noise,
cavitation) are drawn once per acquisition and every channel sees them through
its own transfer path (``model.CHANNELS``), so channels are simultaneous
views of the same event; the fault signatures come from ``faults``. Each run is
also an installation at an operating point: the flow noise and vane pass scale
with the operating point, shared by every channel (and by the classes of one
session, ``faults.SESSIONS``), and each channel's response to the healthy
machine and to flow noise with its mounting, drawn per healthy run, or per fault
class (shared by its levels), calibrated to the real archive's spread
(docs/data.md). All draws come from ``seeding.rng(seed, machine, run, class or
session, ...)``: the same seed gives bit-identical signals
whatever the selection or loading order. Generation is vectorised: harmonics
as complex exponentials, impulse trains by index arithmetic filtered by
band-pass resonators (``scipy.signal.lfilter``), cavitation as band-passed
noise under burst envelopes (``fftconvolve``).
"""

from __future__ import annotations

from functools import cache

import numpy as np
from scipy import signal

from sdt_framework.seeding import rng

from . import faults as f
from . import mix
from . import model as m

__all__ = ["FS_HZ", "generate_run"]

FS_HZ = 20000.0


def _clipped_normal(gen: np.random.Generator, sd: float, limit: float, size: int | None = None):
    return np.clip(gen.normal(0.0, sd, size), -limit * sd, limit * sd)


@cache
def _resonator(freq: float, zeta: float, fs: float) -> tuple[np.ndarray, np.ndarray, float]:
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
    table = [
        (0, g, k, a * (hydraulic if k % m.VANES == 0 else 1.0), "base") for g, k, a in m.BASELINE
    ]
    step = f.SEVERITY_STEPS.get(condition, range(1, level + 1))[level - 1]
    table += [(1, g, k, a * step, condition) for g, k, a in f.FAULT_HARMONICS.get(condition, ())]
    for part, group, order, amp, tag in table:
        phase = rng(seed, machine.name, "phase", group, order, tag).uniform(0, 2 * np.pi)
        key = (group, float(order))
        terms = parts[part]
        terms[key] = terms.get(key, 0j) + amp * scatter[group] * np.exp(1j * phase)
    return parts


def _sources(
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
    run_gen = rng(seed, machine.name, run, "run")
    speed = 1 + _clipped_normal(run_gen, m.SPEED_JITTER, 3)
    groups = ("motor_radial", "motor_axial", "pump_radial", "pump_axial", "impacts", "cavitation")
    scatter = dict(
        zip(groups, np.exp(_clipped_normal(run_gen, m.AMPLITUDE_SCATTER, 2, 6)), strict=True)
    )
    scatter["hydraulic"] = point**m.VANE_PASS_EXPONENT
    gen = rng(seed, machine.name, run, "acquisition", acq)
    f1 = machine.shaft_hz * speed * (1 + _clipped_normal(gen, 5e-4, 3))
    theta = gen.uniform(0, 2 * np.pi)  # shaft angle at the first sample
    t = np.arange(n) / fs
    drift = np.exp(_clipped_normal(gen, m.ACQUISITION_DRIFT, 3, 2))  # (low, broadband)
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
        steps = (1 + _clipped_normal(gen, slip, 3, count)) / rate
        times = gen.uniform(0, 1 / rate) + np.cumsum(steps) - steps[0]
        amps = amp * size * scatter["impacts"] * (1 + _clipped_normal(gen, scatter_sd, 3, count))
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
        strength = amp * np.exp(_clipped_normal(gen, 0.35, 3, chosen.size))
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


def _channel(src: dict, path: m.ChannelPath, noise: np.ndarray, fs: float, install: tuple):
    """One sensor's view of the sources, as the parts ``mix.mix_column`` weighs.

    ``low``: the shaft-synchronous lines through the complex gains; ``fault``: impacts
    ringing the casing resonances and the cavitation bursts; ``broadband``: flow noise
    through the resonances, the valve's hiss and the sensor's own noise. ``install`` =
    (low, broadband): this run's factors on the channel's response to the healthy
    machine's shaft-synchronous vibration, and to flow noise, per resonance.
    """
    out = np.zeros(noise.size, dtype=complex)
    base, fault = src["lowfreq"]
    for group, wave in base.items():
        out += path.gains[group] * install[0] * wave
    for group, wave in fault.items():
        out += path.gains[group] * wave
    impacts = path.cavitation * src["cavitation"]
    excitation = sum(path.impacts[k] * v for k, v in src["impacts"].items())
    broadband = noise + path.cavitation * src["hiss"]
    flow = src["flow"] * m.FLOW_NOISE_G
    for (freq, zeta, weight), mount in zip(path.modes, install[1], strict=True):
        b, a, gain = _resonator(freq, zeta, fs)
        broadband = broadband + weight * signal.lfilter(b, a, mount * flow / gain)
        if np.any(excitation):
            impacts = impacts + weight * signal.lfilter(b, a, excitation)
    return {"low": out.real, "fault": impacts, "broadband": broadband}


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
    glitches: bool = True,
) -> dict[str, np.ndarray]:
    """Generate one run: channel -> float64 (acquisitions, round(duration_s * fs)) in g.

    Parameters
    ----------
    machine, condition, level
        e.g. ("Motor-4", "align angular", 3); for healthy, ``level`` numbers the run.
    channels
        Subset of ``ch1``..``ch5`` (and ``ch6``, the triaxial node's horizontal axis).
    acquisitions, duration_s
        Number and length (s) of continuous acquisitions.
    seed
        Base seed; every draw derives from (seed, machine, run, ...).
    glitches
        Add the real archive's common-mode glitches (``mix.add_glitch``).
    """
    spec = m.MACHINES[machine]
    run = f"{condition} {level}"
    severity = 1 if condition == "healthy" else level
    n = round(duration_s * fs)
    out = {ch: np.empty((acquisitions, n)) for ch in channels}
    # installation: each healthy run is its own; the levels of a fault class share the
    # class campaign's, each level with a small residual of its own. The operating point
    # (flow noise) is shared by the channels, and by the classes of one session, as is
    # the mounting where the session leaves it in place; the mounting is drawn per
    # channel and resonance, so independent of which channels are selected.
    campaign, own_sd = (run, (0.0, 0.0)) if condition == "healthy" else (condition, m.LEVEL_SCATTER)
    session = f.SESSIONS.get(campaign, campaign)
    point_gen = rng(seed, machine, session, "flow point")
    point = np.exp(_clipped_normal(point_gen, m.FLOW_POINT_SD, 2.5))
    install = {}
    for ch in channels:
        mounting = session if session in f.MOUNTING_KEPT else campaign
        gen = rng(seed, machine, mounting, "install", ch)
        own = rng(seed, machine, run, "level", ch)
        path = m.channel_path(ch)
        low = _clipped_normal(gen, path.install_sd, 2.5) + _clipped_normal(own, own_sd[0], 2.5)
        highs = _clipped_normal(gen, m.HF_MOUNT_SD, 2.5, len(path.modes))
        install[ch] = (
            float(np.exp(low)),
            tuple(point * np.exp(highs + _clipped_normal(own, own_sd[1], 2.5))),
        )
    drift = mix.column_drift(
        rng(seed, machine, run, "acquisition drift"),
        {ch: rng(seed, machine, run, "column drift", ch) for ch in channels},
        acquisitions,
    )
    for acq in range(acquisitions):
        src = _sources(spec, condition, severity, run, acq, n, seed, fs, point)
        for ch in channels:
            noise = rng(seed, machine, run, "noise", acq, ch).normal(0, m.SENSOR_NOISE_G, n)
            path = m.channel_path(ch)
            rms, kurt, crest = mix.target(machine, run, ch)
            spread = rng(seed, machine, run, "column spread", acq, ch)
            goal = mix.column_goal(ch, (rms * drift[ch][acq], kurt, crest), spread)
            mode = _resonator(*path.modes[0][:2], fs)[:2]
            out[ch][acq] = mix.mix_column(
                _channel(src, path, noise, fs, install[ch]),
                goal,
                mode,
                (*src["tone"], rng(seed, machine, run, "tone", ch).uniform(0, 2 * np.pi)),
                rng(seed, machine, run, "knocks", acq, ch),
                mix.measured(machine, run),
            )
        if glitches:
            mix.add_glitch(rng(seed, machine, run, "glitch", acq), out, acq, condition == "healthy")
    for x in out.values():
        np.clip(x, -m.FULL_SCALE_G, m.FULL_SCALE_G, out=x)
    return out
