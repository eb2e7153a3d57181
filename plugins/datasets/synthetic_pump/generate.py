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
session, ...)``: the same seed gives bit-identical signals whatever the
selection or loading order. At another speed (``speeds.py``) the run keeps its
installation and draws its acquisitions anew. The sources are drawn in
``sources.py``; here each channel's path and mix.
"""

from __future__ import annotations

import numpy as np
from scipy import signal

from sdt_framework.seeding import rng

from . import faults as f
from . import mix, speeds
from . import model as m
from .sources import clipped_normal, resonator, sources

__all__ = ["FS_HZ", "generate_run"]

FS_HZ = 20000.0


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
        b, a, gain = resonator(freq, zeta, fs)
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
    speed: float | None = None,
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
    speed
        % of rated speed (``speeds.toml``: Motor-2 50, 75 or 100); None: the machine's
        paper point, generated exactly as before speeds existed.
    """
    spec = speeds.machine_at(machine, speed)
    draws = spec.draws  # the acquisitions' draws: the speed's own (the default: the name)
    run = f"{condition} {level}"
    severity = 1 if condition == "healthy" else level
    n = round(duration_s * fs)
    out = {ch: np.empty((acquisitions, n)) for ch in channels}
    # installation: each healthy run is its own; the levels of a fault class share the
    # class campaign's, each level with a small residual of its own. The operating point
    # (flow noise) is shared by the channels, and by the classes of one session, as is
    # the mounting where the session leaves it in place; the mounting is drawn per
    # channel and resonance, so independent of which channels are selected. A run at another
    # speed keeps its installation (the drive's speed changed, the rig and valves untouched:
    # by the affinity laws the pump stays at the same share of its best-efficiency flow).
    campaign, own_sd = (run, (0.0, 0.0)) if condition == "healthy" else (condition, m.LEVEL_SCATTER)
    session = f.SESSIONS.get(campaign, campaign)
    point_gen = rng(seed, machine, session, "flow point")
    point = np.exp(clipped_normal(point_gen, m.FLOW_POINT_SD, 2.5))
    install = {}
    for ch in channels:
        mounting = session if session in f.MOUNTING_KEPT else campaign
        gen = rng(seed, machine, mounting, "install", ch)
        own = rng(seed, machine, run, "level", ch)
        path = m.channel_path(ch)
        low = clipped_normal(gen, path.install_sd, 2.5) + clipped_normal(own, own_sd[0], 2.5)
        highs = clipped_normal(gen, m.HF_MOUNT_SD, 2.5, len(path.modes))
        install[ch] = (
            float(np.exp(low)),
            tuple(point * np.exp(highs + clipped_normal(own, own_sd[1], 2.5))),
        )
    drift = mix.column_drift(
        rng(seed, draws, run, "acquisition drift"),
        {ch: rng(seed, draws, run, "column drift", ch) for ch in channels},
        acquisitions,
    )
    for acq in range(acquisitions):
        src = sources(spec, condition, severity, run, acq, n, seed, fs, point)
        for ch in channels:
            noise = rng(seed, draws, run, "noise", acq, ch).normal(0, m.SENSOR_NOISE_G, n)
            path = m.channel_path(ch)
            rms, kurt, crest = speeds.target(spec, run, ch)
            spread = rng(seed, draws, run, "column spread", acq, ch)
            goal = mix.column_goal(ch, (rms * drift[ch][acq], kurt, crest), spread)
            mode = resonator(*path.modes[0][:2], fs)[:2]
            out[ch][acq] = mix.mix_column(
                _channel(src, path, noise, fs, install[ch]),
                goal,
                mode,
                (*src["tone"], rng(seed, draws, run, "tone", ch).uniform(0, 2 * np.pi)),
                rng(seed, draws, run, "knocks", acq, ch),
                speeds.measured(spec, run),
            )
        if glitches:
            mix.add_glitch(rng(seed, draws, run, "glitch", acq), out, acq, condition == "healthy")
    for x in out.values():
        np.clip(x, -m.FULL_SCALE_G, m.FULL_SCALE_G, out=x)
    return out
