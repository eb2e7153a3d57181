"""How a part reaches its output rate, with its source: ``[sampling]`` in a part file.

In a part file::

    [sampling]
    model = "decimate"
    doc = "ds"
    where = "Filter section, p. 23: low-pass digital decimation filter"
    stopband = "not stated in the text; Figure 60 plots the response"
    stopband_model = "the part's digital filter (8th-order stand-in) at the input rate"

``model`` is the SensorSpec field ``sampling``: "decimate" for a sigma-delta
part whose digital low-pass is its decimation filter (it runs at the
modulator rate, before the output rate), "sample-then-filter" for the
paper's model. ``stopband`` says what the documents give of the filter's
attenuation at and above the output Nyquist frequency (or that they give
none), ``stopband_model`` what the chain uses in its place. A part without
``[sampling]`` keeps the paper's model. A mode without a digital low-pass
has no decimation filter to move: it samples, and its provenance says so.
"""

from __future__ import annotations

from pydantic import Field

from ..specs.sensor import PAPER_SAMPLING, Sampling
from .values import Basis, Model

__all__ = ["PartSampling"]


class PartSampling(Model):
    """The sampling model of a part, where it is documented, and its stopband."""

    model: Sampling
    doc: str = Field(min_length=1, description="Id of a document of the part.")
    where: str = Field(min_length=1, description="Section, page, table or figure.")
    basis: Basis = "nominal"
    stopband: str = Field(
        default="",
        description="What the documents state of the attenuation at and above the output "
        "Nyquist frequency, or that they state none.",
    )
    stopband_model: str = Field(
        default="", description="The model the chain uses for that stopband, and why."
    )
    note: str = ""

    @property
    def paper(self) -> bool:
        """True for the paper's sample-then-filter model."""
        return self.model == PAPER_SAMPLING
