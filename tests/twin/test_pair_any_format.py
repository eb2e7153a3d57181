"""A TOML pair names files of any registered format; rate and units come from the files.

The same synthetic pair (a 20 kHz reference of four tones, and the adxl345 twin of it at
3125 Hz) written twice: as NPY arrays with ``rate_hz`` in the pair file, and as a TDMS
reference in m/s^2 (npTDMS, ``wf_increment``) with a UFF58 device in g (pyuff,
``abscissa_inc``) with no rate or units in the pair file. Both pairs hold the same signals and
check alike. Before, a pair's file had to be CSV, NPY or MAT and ``rate_hz`` was required.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sdt_framework.api import degrade
from sdt_framework.twin import check_twin, load_pair
from sdt_framework.twin.align import at_rate

FS_REF = 20_000.0
RATE = 3125.0  # 1 / RATE = 3.2e-4 s, printed exactly in the UFF header
G0 = 9.80665
UFF_TEMPLATE = Path(__file__).parents[1] / "data" / "readers" / "binary8byte.uff"


@pytest.fixture(scope="module")
def pairs(registry, tmp_path_factory) -> tuple[Path, Path]:
    import pyuff
    from nptdms import ChannelObject, TdmsWriter

    t = np.arange(int(4 * FS_REF)) / FS_REF
    reference = 1e-6 * np.random.default_rng(3).normal(size=t.size)
    for f in (80, 160, 315, 630):
        reference += np.sin(2 * np.pi * f * t)
    device, _ = degrade(reference, FS_REF, at_rate(registry.sensor("adxl345"), RATE), seed=7)
    folder = tmp_path_factory.mktemp("pairs")
    np.save(folder / "ref.npy", reference)
    np.save(folder / "dev.npy", device)
    (folder / "npy.toml").write_text(
        '[reference]\nfile = "ref.npy"\naxes = ["x"]\nrate_hz = 20000.0\n\n'
        f'[device]\nfile = "dev.npy"\naxes = ["x"]\nrate_hz = {RATE}\n'
    )
    props = {"wf_increment": 1 / FS_REF, "unit_string": "m/s^2"}
    with TdmsWriter(folder / "ref.tdms") as writer:
        writer.write_segment([ChannelObject("piezo", "x", reference * G0, properties=props)])
    template = pyuff.UFF(str(UFF_TEMPLATE)).read_sets(0)  # a time history in g
    pyuff.UFF(str(folder / "dev.uff")).write_sets(
        {**template, "data": device, "num_pts": device.size,
         "x": np.arange(device.size) / RATE, "abscissa_inc": 1 / RATE}, mode="add")  # fmt: skip
    (folder / "daq.toml").write_text(
        '[reference]\nfile = "ref.tdms"\naxes = ["x"]\n\n[device]\nfile = "dev.uff"\naxes = ["x"]\n'
    )
    return folder / "npy.toml", folder / "daq.toml"


def test_a_pair_of_daq_files_takes_rate_and_units_from_them(pairs, registry):
    readers = registry.signal_readers()
    arrays, daq = (load_pair(p, "adxl345", readers=readers) for p in pairs)
    for a, b in ((arrays.reference, daq.reference), (arrays.device, daq.device)):
        assert b.rate_hz == pytest.approx(a.rate_hz, rel=1e-12)
        np.testing.assert_allclose(b.values, a.values, rtol=1e-12, atol=1e-15)
    sensor = registry.sensor("adxl345")
    for a, b in zip(check_twin(arrays, sensor).bands, check_twin(daq, sensor).bands, strict=True):
        assert b.real_rms_g == pytest.approx(a.real_rms_g, rel=1e-9)
        assert b.judgeable == a.judgeable


def test_a_pair_is_read_only_by_the_readers_handed_down(pairs, registry):
    # the twin never looks a registry up: the readers are a required argument, and a pair
    # whose files no reader handed down reads is refused naming the formats it was given
    from sdt_framework.errors import SDTError

    with pytest.raises(TypeError, match="readers"):
        load_pair(pairs[1], "adxl345")  # type: ignore[call-arg]
    tdms_only = [r for r in registry.signal_readers() if r.name == "tdms"]
    with pytest.raises(SDTError, match=r"dev\.uff: format not recognised.*sdt reads TDMS"):
        load_pair(pairs[1], "adxl345", readers=tdms_only)
