"""degrade(): reference identity, determinism, batching, caching, rates."""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.api import degrade
from sdt_framework.chain import compile_chain
from sdt_framework.specs import SensorSpec


@pytest.fixture
def batch() -> np.ndarray:
    t = np.arange(24000) / 20000
    rng = np.random.default_rng(7)
    return np.sin(2 * np.pi * 97 * t) + 0.3 * rng.standard_normal((4, t.size))


def test_reference_profile_returns_the_recording_bit_identical(
    reference: SensorSpec, batch: np.ndarray
) -> None:
    y, fs = degrade(batch, 20000, reference, seed=9)
    assert fs == 20000
    assert y.dtype == np.float64
    np.testing.assert_array_equal(y, batch)
    y32, _ = degrade(batch.astype(np.float32), 20000, reference)
    np.testing.assert_array_equal(y32, batch.astype(np.float32).astype(np.float64))
    assert y is not batch  # a copy, the caller's array is never modified


def test_output_shape_rate_and_ndim(mems: SensorSpec, batch: np.ndarray) -> None:
    y, fs = degrade(batch, 20000, mems)
    m = int((batch.shape[1] - 1) * mems.sampling_rate_hz / 20000) + 1
    assert fs == mems.sampling_rate_hz and y.shape == (4, m)
    one, _ = degrade(batch[0], 20000, mems)
    assert one.ndim == 1 and one.shape == (m,)


def test_same_seed_is_bit_identical_and_another_seed_differs(
    mems: SensorSpec, batch: np.ndarray
) -> None:
    a, _ = degrade(batch, 20000, mems, seed=11)
    b, _ = degrade(batch, 20000, mems, seed=11)
    c, _ = degrade(batch, 20000, mems, seed=12)
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a, c)


def test_batch_equals_one_by_one(mems: SensorSpec, batch: np.ndarray) -> None:
    whole, _ = degrade(batch, 20000, mems, seed=4, first_index=10)
    for k, row in enumerate(batch):
        alone, _ = degrade(row, 20000, mems, seed=4, first_index=10 + k)
        np.testing.assert_array_equal(alone, whole[k])
    ids, _ = degrade(batch[2:3], 20000, mems, seed=4, acquisition_ids=[12])
    np.testing.assert_array_equal(ids[0], whole[2])


def test_thread_count_does_not_change_the_output(adxl357: SensorSpec, batch: np.ndarray) -> None:
    one, _ = degrade(batch, 20000, adxl357, threads=1)
    two, _ = degrade(batch, 20000, adxl357, threads=3)
    np.testing.assert_array_equal(one, two)


def test_chain_is_compiled_once_per_profile_content_and_rate(adxl345: SensorSpec) -> None:
    first = compile_chain(adxl345, 20000)
    stamped = adxl345.model_copy(update={"plugin": "other", "distribution": "x"})
    assert compile_chain(stamped, 20000.0) is first
    assert compile_chain(adxl345, 40000) is not first
    changed = adxl345.model_copy(update={"noise_density_ug_rthz": 100})
    assert compile_chain(changed, 20000) is not first
    # mechanical and analog filters run as one fused SOS cascade at F_ref
    assert [s.name for s in first.stages] == [
        "mechanical+analog",
        "sample",
        "noise",
        "digital",
        "quantise",
    ]


def test_a_new_stage_is_one_more_item_in_the_tuple(adxl345: SensorSpec) -> None:
    from dataclasses import dataclass

    from sdt_framework.chain import RunContext

    @dataclass(frozen=True)
    class Offset:
        fs_in: float
        name: str = "offset"

        @property
        def fs_out(self) -> float:
            return self.fs_in

        def apply(self, x: np.ndarray, ctx: RunContext) -> np.ndarray:
            return x + 0.5

    chain = compile_chain(adxl345, 20000)
    extended = chain.with_stages([*chain.stages[:-1], Offset(3200), chain.stages[-1]])
    y = extended.run(np.zeros((1, 2000)), RunContext(noise=False, acquisition_ids=(0,)))
    assert np.all(y == 0.5)  # 0.5 g is a multiple of the 3.9 mg step
