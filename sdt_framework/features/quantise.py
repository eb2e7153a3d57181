"""Features as the node sends them: each column rounded to its on-node dtype.

A feature set declares the type its values travel in (``FeatureSetSpec.dtype``;
per part for a composed set). :func:`quantise_features` rounds each float32
column to that type and back, so a classifier sees exactly what a gateway
would decode, and the cost of sending float16 instead of float32 is measured by
the benchmark rather than assumed. Rounding is IEEE round-to-nearest-even
(numpy ``astype``); float16 keeps 11 significant bits (relative step 2**-10
near 1) and values below 6e-8 in magnitude become 0, as on the node. A value
beyond float16's range (65504) is an error, never a silent infinity.
"""

from __future__ import annotations

import numpy as np

from ..errors import SDTError
from ..specs import FeatureSetSpec

__all__ = ["quantise_features"]


def quantise_features(
    values: np.ndarray, feature_set: FeatureSetSpec, *, where: str = ""
) -> np.ndarray:
    """Round each column of ``values`` to the on-node dtype of its feature.

    Parameters
    ----------
    values
        Features, shape (n_windows, n_features), in ``feature_set`` column order.
    feature_set
        Declares each column's on-node dtype (``value_dtypes``).
    where
        What the values belong to (a recording), quoted in an overflow error.

    Returns
    -------
    numpy.ndarray
        ``values`` itself when every column is float32 (nothing to round);
        otherwise a float32 copy holding the rounded values.

    Raises
    ------
    SDTError
        A finite value outside the range of its column's dtype.
    """
    dtypes = feature_set.value_dtypes
    if all(d == "float32" for d in dtypes):
        return values
    out = np.array(values, dtype=np.float32)
    for dtype in sorted(set(dtypes) - {"float32"}):
        cols = np.flatnonzero([d == dtype for d in dtypes])
        block = out[:, cols]
        with np.errstate(over="ignore"):
            rounded = block.astype(dtype)
        bad = np.isfinite(block) & ~np.isfinite(rounded)
        if bad.any():
            row, col = (int(i) for i in np.argwhere(bad)[0])
            name = feature_set.feature_names[cols[col]]
            raise SDTError(
                f"feature {name!r} = {float(block[row, col]):g} in window {row}"
                f"{f' of {where}' if where else ''} does not fit {dtype} (largest "
                f"{float(np.finfo(dtype).max):g}); send it as float32 "
                f'(feature_dtype = "float32")'
            )
        out[:, cols] = rounded.astype(np.float32)
    return out
