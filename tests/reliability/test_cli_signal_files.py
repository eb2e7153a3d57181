"""The commands that take a signal file refuse what the file contradicts (issue 41 item 12).

``sdt degrade``, ``sdt features extract``, ``sdt validate-noise --recording`` and a twin pair
read a file through the registered readers, with the rate and units the file states: a
``--fs`` (or a pair's ``rate_hz``) that contradicts the file is one line naming both rates,
exit 2, nothing written; so is a file holding several signals without ``--signal``, a file
holding no rate without ``--fs``, units that are no acceleration, and a reader option the
file's format does not take. Files are written by their formats' own libraries, or are the
real files of ``tests/data``. Before, every one of these commands refused every format but
.npy/.csv (``features extract``: but .npy) as an unsupported file type.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from .labview import lvm, segment

FS = 20000.0
ENDAQ = Path(__file__).parents[1] / "data" / "endaq"
READERS = Path(__file__).parents[1] / "data" / "readers"


def _tone(n: int = 40_000) -> np.ndarray:
    return 0.5 * np.sin(2 * np.pi * 50 * np.arange(n) / FS)


@pytest.fixture(scope="module")
def files(tmp_path_factory) -> dict[str, Path]:
    """A file per format that states its rate (20 kHz; the IDE file its own, 4999.48 Hz)."""
    import pyuff
    import scipy.io.wavfile
    from nptdms import ChannelObject, TdmsWriter

    folder = tmp_path_factory.mktemp("rated")
    x = _tone()
    props = {"wf_increment": 1 / FS, "unit_string": "m/s^2"}
    with TdmsWriter(folder / "two.tdms") as writer:
        writer.write_segment([
            ChannelObject("acc", "x", x * 9.80665, properties=props),
            ChannelObject("env", "temp", np.full(x.size, 21.0),
                          properties={**props, "unit_string": "degC"}),
        ])  # fmt: skip
    template = pyuff.UFF(str(READERS / "binary8byte.uff")).read_sets(0)
    pyuff.UFF(str(folder / "rec.uff")).write_sets(
        {**template, "data": x, "num_pts": x.size, "x": np.arange(x.size) / FS,
         "abscissa_inc": 1 / FS}, mode="add")  # fmt: skip
    (folder / "rec.lvm").write_text(lvm([segment(["acc"], x[:, None], 1 / FS)]))
    scipy.io.wavfile.write(folder / "rec.wav", int(FS), x.astype(np.float32))
    np.save(folder / "rec.npy", x)
    return {
        "tdms": folder / "two.tdms",
        "uff58": folder / "rec.uff",
        "lvm": folder / "rec.lvm",
        "wav": folder / "rec.wav",
        "ide": ENDAQ / "SSX_Data.IDE",
        "npy": folder / "rec.npy",
    }


#: the signal each command reads, and the file's own rate as printed
SIGNAL = {"tdms": ("acc/x", "20000"), "uff58": (None, "20000"), "lvm": (None, "20000"),
          "wav": (None, "20000"), "ide": ("8:x", "4999.48")}  # fmt: skip


def _refused(run: tuple[int, str, str]) -> str:
    code, _, err = run
    assert code == 2, err
    assert err.startswith("error: ") and err.count("\n") == 1 and "Traceback" not in err, err
    return err.strip()


@pytest.mark.parametrize("fmt", sorted(SIGNAL))
@pytest.mark.parametrize("command", ["degrade", "features"])
def test_a_fs_that_contradicts_the_file_is_refused_naming_both(
    sdt_main, tmp_path, files, fmt, command
):
    signal, rate = SIGNAL[fmt]
    chosen = ["--signal", signal] if signal else []
    out = tmp_path / ("y.npy" if command == "degrade" else "f.csv")
    head = ["degrade", str(files[fmt]), "--sensor", "adxl345"] if command == "degrade" else \
        ["features", "extract", str(files[fmt])]  # fmt: skip
    line = _refused(sdt_main(*head, *chosen, "--fs", "25600", "--out", str(out)))
    assert f"runs at {rate} Hz by its " in line and "--fs says 25600 Hz" in line, line
    assert "drop --fs to take the file's rate" in line and str(files[fmt]) in line
    assert not out.exists()


def test_validate_noise_refuses_a_fs_that_contradicts_the_recording(sdt_main, files):
    """Before: the IDE's measured 3134.31 Hz was silently replaced by --fs."""
    line = _refused(sdt_main("validate-noise", "--sensor", "adxl345", "--axis", "z",
                             "--recording", str(files["ide"]), "--windows", "4",
                             "--fs", "3200"))  # fmt: skip
    assert "signal '32:z': runs at 3134.31 Hz by its timestamps, --fs says 3200 Hz" in line


def test_a_fs_within_the_readers_tolerance_is_taken(sdt_main, tmp_path, files):
    """The IDE rate is measured (0.1 % tolerated, as a manifest's rate is)."""
    out = tmp_path / "y.npy"
    code, stdout, err = sdt_main("degrade", str(files["ide"]), "--signal", "8:x", "--sensor",
                                 "adxl345", "--fs", "5000", "--out", str(out))  # fmt: skip
    assert code == 0, err
    assert "at 5000 Hz (--fs)" in stdout


def test_a_file_of_several_signals_lists_them_and_names_the_option(sdt_main, tmp_path, files):
    out = tmp_path / "y.npy"
    line = _refused(sdt_main("degrade", str(files["tdms"]), "--sensor", "adxl345",
                             "--out", str(out)))  # fmt: skip
    assert "holds 2 signals ('acc/x', 'env/temp'); choose one with --signal NAME" in line
    line = _refused(sdt_main("features", "extract", str(files["tdms"]), "--signal", "acc/z",
                             "--out", str(tmp_path / "f.csv")))  # fmt: skip
    assert "no signal 'acc/z'; it holds 'acc/x', 'env/temp'" in line


def test_a_file_holding_no_rate_needs_fs(sdt_main, tmp_path, files):
    line = _refused(sdt_main("degrade", str(files["npy"]), "--sensor", "adxl345",
                             "--out", str(tmp_path / "y.npy")))  # fmt: skip
    assert line.endswith("rec.npy: no sampling rate in this NPY file; give it with --fs (Hz)")


def test_units_that_are_no_acceleration_are_refused(sdt_main, tmp_path, files):
    """npTDMS's 'degC' channel, and the real LabVIEW file's force channel in Newtons."""
    line = _refused(sdt_main("degrade", str(files["tdms"]), "--signal", "env/temp",
                             "--sensor", "adxl345", "--out", str(tmp_path / "y.npy")))  # fmt: skip
    assert "signal 'env/temp': the file gives its units as 'degC', not an acceleration" in line
    line = _refused(sdt_main("features", "extract", str(READERS / "short.lvm"), "--signal",
                             "Excitation (Trigger)", "--out", str(tmp_path / "f.csv")))  # fmt: skip
    assert "the file gives its units as 'Newtons', not an acceleration (g, mg, m/s^2)" in line


def test_validate_noise_unit_that_contradicts_the_file_is_refused(sdt_main, files):
    line = _refused(sdt_main("validate-noise", "--sensor", "adxl345", "--recording",
                             str(files["tdms"]), "--signal", "acc/x", "--unit", "lsb",
                             "--scale", "0.0039"))  # fmt: skip
    assert "the file gives its units as 'm/s^2', --unit says lsb; drop --unit" in line


def test_reader_options_name_their_flag_and_apply_only_where_they_can(sdt_main, tmp_path, files):
    """The integer WAV from SciPy's tests needs its full scale; a TDMS file takes none."""
    line = _refused(sdt_main("degrade", str(READERS / "test-44100Hz-le-1ch-4bytes.wav"),
                             "--sensor", "adxl345", "--out", str(tmp_path / "y.npy")))  # fmt: skip
    assert "integer PCM (32-bit) samples are counts, not g" in line
    assert line.endswith("; here: give it with --full-scale-g")
    line = _refused(sdt_main("degrade", str(files["tdms"]), "--signal", "acc/x",
                             "--full-scale-g", "2", "--sensor", "adxl345",
                             "--out", str(tmp_path / "y.npy")))  # fmt: skip
    assert "two.tdms: --full-scale-g does not apply to this TDMS file; drop it" in line
    line = _refused(sdt_main("validate-noise", "--sensor", "adxl345", "--recording",
                             str(files["npy"]), "--channel", "32"))  # fmt: skip
    assert "--channel is for an .IDE recording without --signal; drop it" in line


def test_a_pair_rate_that_contradicts_its_file_is_refused(sdt_main, tmp_path, files):
    """A twin pair's side is read as `sdt degrade` reads a file: its rate_hz is checked."""
    (tmp_path / "pair.toml").write_text(
        f'[reference]\nfile = "{files["tdms"]}"\nvariable = "acc/x"\naxes = ["x"]\n'
        f'rate_hz = 25600\n\n[device]\nfile = "{files["npy"]}"\naxes = ["x"]\nrate_hz = 3200\n'
    )
    line = _refused(sdt_main("twin", "check", str(tmp_path / "pair.toml"), "--sensor",
                             "adxl345"))  # fmt: skip
    assert "signal 'acc/x': runs at 20000 Hz by its wf_increment, rate_hz in [reference] " \
           "says 25600 Hz" in line  # fmt: skip
