"""``sdt twin check``: the twin of a sensor against what the real device recorded.

After alignment (:mod:`.align`), each axis is compared band by band (third
octaves from 10 Hz to the device's Nyquist): the device's band RMS, the
twin's, and the twin's error in dB. A band is *judgeable* only where the
reference carries information: its band power at least :data:`MARGIN_DB`
above the reference's own floor there (the median density of its tone-free
bins within an octave either side, times the bandwidth: a floor that rises
toward low frequencies is not taken for motion), and
the band below the reference's band limit (:data:`REFERENCE_LIMIT` of its
rate: a 5 kHz piezo channel cannot judge a 2.4 kHz band, whatever its
numbers say). The summary is the worst judgeable band error and the RMS of
the judgeable errors. Also reported: the transfer function twin -> device
(Welch cross-spectra) with its coherence at each judgeable band's strongest
bin, the noise floors, the harmonic distortion of the dominant tone and the
samples at full scale (:mod:`.clipping`: counted per axis, never a refusal).

The floors are read from the seconds where nothing moves (:mod:`.floor`:
per-segment Welch spectra, the quietest segments averaged), not from the
median over frequency of the whole record: random vibration and shocks lift
every bin of that median, which then reads the motion as floor.

Two readings say what the pair itself can and cannot tell:

- A noise floor is judged only where the reference's floor lies at least
  :data:`MARGIN_DB` below the device's: the twin's floor is the reference's
  plus the modelled noise, so a reference as noisy as the part (a 100 g
  piezo beside an ADXL357) shows its own floor, not the twin's error.
- A DC-coupled device at rest on its mount reads gravity: the length of its
  mean vector, against 1 g, checks its own static calibration without the
  reference (one orientation cannot separate sensitivity from 0 g offset,
  hence the :data:`STATIC_TOLERANCE`). When that holds and the twin still
  disagrees in gain at the dominant tone, the disagreement is the
  reference's calibration, not the part's, and ``sdt twin fit`` does not
  write it into the profile; unless a first cause explains the gain (a
  device rate that is not the part's, clipping) or no tone gives one
  (:mod:`.verdict`).
"""

from __future__ import annotations

import numpy as np

from ..errors import SDTError
from ..specs import SensorSpec
from . import floor, spectra
from .align import Alignment, align
from .clipping import clipping
from .pair import Pair
from .results import (
    AlignmentInfo,
    Band,
    CheckResult,
    CheckSpectra,
    DeviceInfo,
    Distortion,
    Floor,
    PairInfo,
    SideInfo,
    Summary,
)
from .transfer import transfer
from .verdict import SCALE_RANGE, STATIC_TOLERANCE, calibration, check_reference_scale, no_band

__all__ = [
    "MARGIN_DB",
    "REFERENCE_LIMIT",
    "SCALE_RANGE",
    "STATIC_TOLERANCE",
    "CheckResult",
    "check_reference_scale",
    "check_twin",
    "in_sample",
]

#: a band is judgeable when the reference stands this far above its own floor
MARGIN_DB = 10.0
#: ... and lies below this share of the reference's rate (its front end's band)
REFERENCE_LIMIT = 0.4


def in_sample(sensor: SensorSpec, pair: Pair) -> bool:
    """Whether ``sensor`` was fitted on this very file (its provenance names the digest)."""
    return f"sha256 {pair.digest}" in (sensor.source or "")


def _judge(ref_rms: np.ndarray, floor: np.ndarray, bands: np.ndarray, limit: float) -> list:
    """(judgeable, reason) per axis and band; ``floor`` is the local floor density per band."""
    floor_rms = np.sqrt(floor * (bands[None, :, 2] - bands[None, :, 0]))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        above = 20 * np.log10(ref_rms / floor_rms)
    # a floor of 0 or a reference below the smallest float (a reference scaled by 1e-300)
    # says nothing: not judgeable, never "infinitely far above"
    measurable = np.isfinite(above) & (floor_rms > 0) & np.isfinite(floor_rms)
    out = []
    for axis_above, axis_ok in zip(above, measurable, strict=True):
        row = []
        for band, level, ok in zip(bands, axis_above, axis_ok, strict=True):
            if band[2] > limit:
                row.append((False, f"above the reference's band limit ({limit:.0f} Hz)"))
            elif not ok:
                row.append((False, "reference and its floor not measurable (zero or overflow)"))
            elif level < MARGIN_DB:
                where = f"only {level:.1f} dB above" if level >= 0 else f"{-level:.1f} dB below"
                row.append((False, f"reference {where} its floor"))
            else:
                row.append((True, f"reference {level:.1f} dB above its floor"))
        out.append(row)
    return out


def _db(a: float, b: float) -> float:
    """20 log10(a / b); NaN (None in JSON) when either is zero or not finite."""
    ok = a > 0 and b > 0 and np.isfinite(a) and np.isfinite(b)
    return float(20 * np.log10(a / b)) if ok else float("nan")


def _floor_judged(reference: float, device: float) -> tuple[bool, str]:
    """Whether the twin's noise floor can be judged (the reference's must lie well below),
    and why."""
    if not (reference > 0 and np.isfinite(reference) and device > 0 and np.isfinite(device)):
        return False, "a floor of zero or beyond floats: not measurable"
    below = float(20 * np.log10(device / reference))
    if below >= MARGIN_DB:
        return True, f"reference floor {below:.1f} dB below the device's"
    where = f"only {below:.1f} dB below" if below >= 0 else f"{-below:.1f} dB above"
    return False, f"reference floor {where} the device's"


def _pair_info(pair: Pair, sensor: SensorSpec, a: Alignment) -> PairInfo:
    ref, dev = pair.reference, pair.device
    return PairInfo(
        file=pair.name,
        sha256=pair.digest,
        sensor=sensor.name,
        in_sample=in_sample(sensor, pair),
        reference=SideInfo(ref.label, ref.part, ref.rate_hz),
        device=DeviceInfo(dev.label, dev.part, a.rate_hz, a.nominal_rate_hz),
        overlap_s=a.device.shape[1] / a.rate_hz,
        notes=tuple(n for n in (ref.note, dev.note) if n),
    )


def _alignment_info(a: Alignment) -> AlignmentInfo:
    return AlignmentInfo(
        rate_hz=a.rate_hz,
        clock_error_pct=100 * (a.rate_hz / a.nominal_rate_hz - 1),
        delay_s=a.delay_s,
        signs=tuple(a.signs),
        angles_deg=tuple(a.angles_deg),
        rotation=tuple(tuple(row) for row in a.rotation.round(6).tolist()),
        correlation=a.correlation,
        rotation_estimated=a.rotation_estimated,
    )


def check_twin(pair: Pair, sensor: SensorSpec, seed: int = 0) -> CheckResult:
    """Compare ``sensor``'s twin of ``pair.reference`` with ``pair.device``."""
    a = align(pair, sensor, seed)
    ref_rate = pair.reference.rate_hz
    f_ref, p_ref = spectra.psd(a.reference, ref_rate)
    f_dev, p_dev = spectra.psd(a.device, a.rate_hz)
    _, p_twin = spectra.psd(a.twin, a.rate_hz)
    bands = spectra.third_octaves(10.0, a.rate_hz / 2)
    limit = REFERENCE_LIMIT * ref_rate
    count = floor.segments(a.reference.shape[1] / ref_rate, a.device.shape[1] / a.rate_hz)
    ref_segments = floor.segmented(a.reference, ref_rate, count)
    ref_floor = ref_segments.floor_asd(10.0, limit)
    local, _ = ref_segments.local(bands, 10.0, limit)
    judged = _judge(spectra.band_rms(f_ref, p_ref, bands), local, bands, limit)
    if not any(ok for row in judged for ok, _ in row):
        raise SDTError(no_band(pair.name, sensor, a.rate_hz, limit, len(bands), MARGIN_DB))
    real = spectra.band_rms(f_dev, p_dev, bands)
    twin = spectra.band_rms(f_dev, p_twin, bands)
    transfers, (f_h, h, coherence) = transfer(a, bands, judged)
    rows, errors = [], []
    for i, axis in enumerate(pair.device.axes):
        for b, (ok, reason) in enumerate(judged[i]):
            error = _db(twin[i, b], real[i, b])
            rows.append(Band(
                axis, float(bands[b, 0]), float(bands[b, 1]), float(bands[b, 2]),
                real_rms_g=float(real[i, b]), twin_rms_g=float(twin[i, b]), error_db=error,
                judgeable=ok, reason=reason, transfer=transfers.get((i, b)),
            ))  # fmt: skip
            if ok:
                errors.append((abs(error), error, axis, float(bands[b, 1])))
    floors_hi = a.rate_hz / 4  # below the digital corner of either part
    dev_segments = floor.segmented(a.device, a.rate_hz, count)
    quiet = dev_segments.quiet(10.0, floors_hi)  # the device's quiet seconds, for the twin too
    dev_floor = dev_segments.floor_asd(10.0, floors_hi, quiet)
    twin_floor = floor.segmented(a.twin, a.rate_hz, count).floor_asd(10.0, floors_hi, quiet)
    main = int(np.argmax(a.device.std(axis=1)))
    f0 = float(f_dev[np.argmax(p_dev[main, 1:]) + 1])
    worst = max(errors)
    clipped = clipping(a.device, a.twin, pair.device.axes, sensor.full_scale_g)
    floors = []
    for axis, r, t, d, q in zip(pair.device.axes, ref_floor, twin_floor, dev_floor,
                                quiet.sum(axis=1), strict=True):  # fmt: skip
        judgeable, why = _floor_judged(float(r), float(d))
        floors.append(Floor(
            axis, reference_ug=1e6 * float(r), twin_ug=1e6 * float(t), device_ug=1e6 * float(d),
            twin_error_db=_db(t, d), quiet_s=float(q * dev_segments.segment_s),
            of_s=float(count * dev_segments.segment_s), judgeable=judgeable, reason=why,
        ))  # fmt: skip
    return CheckResult(
        pair=_pair_info(pair, sensor, a),
        alignment=_alignment_info(a),
        bands=tuple(rows),
        floors=tuple(floors),
        distortion=Distortion(
            axis=pair.device.axes[main],
            tone_hz=f0,
            reference=spectra.thd(f_ref, p_ref[main], f0),
            twin=spectra.thd(f_dev, p_twin[main], f0),
            device=spectra.thd(f_dev, p_dev[main], f0),
        ),
        clipped=clipped,
        calibration=calibration(
            a.device, transfers, main, clipped, sensor, a.rate_hz, (f_dev, p_dev[main])
        ),
        summary=Summary(
            judgeable_bands=len(errors),
            worst_error_db=worst[1],
            worst_axis=worst[2],
            worst_band_hz=worst[3],
            rms_error_db=float(np.sqrt(np.mean([e[1] ** 2 for e in errors]))),
        ),
        spectra=CheckSpectra(
            f=f_dev, device=p_dev, twin=p_twin, f_ref=f_ref, reference=p_ref, main=main,
            axes=tuple(pair.device.axes), judged=tuple(b for b in rows if b.judgeable),
            f_h=f_h, h=h, coherence=coherence,
        ),
    )  # fmt: skip
