"""What a stage plugin registers (:class:`StageSpec`) and the context its factory gets.

A stage plugin provides a name, a pydantic model of its parameters (units in
the field descriptions), where in the chain it runs and a factory that builds
the stage object. The chain's own stages are the anchors a plugin stage is
placed against, in this order::

    mechanical -> analog -> sample -> noise -> digital -> quantise
    '---- analog domain (recording rate) ----'---- digital domain (output rate) ----'

An analog-domain stage runs at the recording's rate before the sampler; a
digital-domain stage runs at the sensor's output rate after it; a ``sampler``
stage replaces the sampler itself (it picks the sampling instants). A sensor
node stage (``node=True``, e.g. cross-axis sensitivity) also reads the same
acquisitions on the triaxial node's other two axes, ``ctx.node``; it runs
first, on the raw inputs. A sensor
profile lists the stages it adds as :class:`StageUse` entries (name,
parameters, per-axis values, per-unit tolerances); the registry binds each to
its spec, so unknown names and bad parameters are one-line errors.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, ClassVar, Literal

from pydantic import BaseModel, Field, field_validator, model_validator

from ..specs import Spec
from ..specs.stage_use import StageUse, Tolerance

__all__ = [
    "ANCHORS",
    "StageContext",
    "StageSpec",
    "StageUse",
    "Tolerance",
]

#: the chain's own stages, in chain order: the places a plugin stage is put against
ANCHORS = ("mechanical", "analog", "sample", "noise", "digital", "quantise")
Anchor = Literal["mechanical", "analog", "sample", "noise", "digital", "quantise"]
#: (where, anchor) pairs each domain may use
_ALLOWED = {
    "analog": {
        ("before", "mechanical"),
        ("after", "mechanical"),
        ("before", "analog"),
        ("after", "analog"),
        ("before", "sample"),
    },
    "digital": {
        ("after", "sample"),
        ("before", "noise"),
        ("after", "noise"),
        ("before", "digital"),
        ("after", "digital"),
        ("before", "quantise"),
        ("after", "quantise"),
    },
    "sampler": {("before", "sample")},
}


@dataclass(frozen=True)
class StageContext:
    """What a stage factory is told about the chain it builds a stage for.

    Attributes
    ----------
    fs
        Rate the stage runs at, Hz: the recording's for an analog-domain or
        sampler stage, the sensor's output rate for a digital-domain one.
    recording_hz, target_hz
        The recording's rate and the sensor's output data rate, Hz.
    full_scale_g
        The sensor's range, g (None for a profile without one).
    label
        Unique label of this use in the chain (``"gauss-markov.0"``); a random
        stage seeds its draws with it, so two uses never share draws.
    sensor
        Name of the sensor profile (for error messages only, never for seeds).
    """

    fs: float
    recording_hz: float
    target_hz: float
    full_scale_g: float | None
    label: str
    sensor: str


class StageSpec(Spec):
    """A chain stage a plugin provides.

    ``factory(params, context)`` receives a validated instance of ``params``
    and a :class:`StageContext` and returns an object with ``name``,
    ``fs_in``, ``fs_out`` and ``apply(x, ctx)`` (the
    :class:`sdt_framework.chain.Stage` protocol). ``random`` says whether the
    stage draws random numbers (then it draws only when the run's ``noise``
    switch is on, from seeds derived from the run's seed and its label).
    """

    kind: ClassVar[str] = "stage"
    _provenance: ClassVar[frozenset[str]] = frozenset(
        {"plugin", "distribution", "factory", "params"}
    )

    domain: Literal["analog", "digital", "sampler"] = Field(
        description="analog: at the recording rate before sampling; digital: at the output "
        "rate after sampling; sampler: replaces the sampler."
    )
    where: Literal["before", "after"] = Field(
        default="before", description="Before or after the anchor stage."
    )
    anchor: Anchor = Field(
        default="sample",
        description="The built-in stage it is placed by (default: before sample for an "
        "analog or sampler stage, before quantise for a digital one).",
    )
    random: bool = Field(default=False, description="Whether the stage draws random numbers.")
    node: bool = Field(
        default=False,
        description="Whether the stage reads the node's other two axes (ctx.node): it then "
        "runs first in the chain (analog, before mechanical) on the raw inputs.",
    )
    params: type[BaseModel] = Field(exclude=True, description="Pydantic model of the parameters.")
    factory: Callable[..., Any] = Field(
        exclude=True, description="factory(params, context) -> stage object."
    )
    example: dict[str, Any] = Field(
        default_factory=dict, description="Parameters the conformance check builds it with."
    )

    @model_validator(mode="before")
    @classmethod
    def _default_place(cls, data: Any) -> Any:
        if isinstance(data, dict) and data.get("domain") == "digital" and "anchor" not in data:
            return {**data, "anchor": "quantise"}
        return data

    @model_validator(mode="after")
    def _check_place(self) -> StageSpec:
        allowed = _ALLOWED[self.domain]
        if (self.where, self.anchor) not in allowed:
            places = ", ".join(f"{w} {a}" for w, a in sorted(allowed))
            raise ValueError(
                f"a {self.domain} stage cannot run {self.where} {self.anchor}; use one of: {places}"
            )
        return self

    @model_validator(mode="after")
    def _check_node(self) -> StageSpec:
        place = (self.domain, self.where, self.anchor)
        if self.node and place != ("analog", "before", "mechanical"):
            raise ValueError(
                "a node stage (node=True) reads the other axes' raw inputs, so it must be an "
                "analog stage placed before mechanical"
            )
        return self

    @model_validator(mode="after")
    def _check_example(self) -> StageSpec:
        self.params.model_validate(self.example)
        return self

    @field_validator("params")
    @classmethod
    def _check_params(cls, value: type[BaseModel]) -> type[BaseModel]:
        if not (isinstance(value, type) and issubclass(value, BaseModel)):
            raise ValueError("params must be a pydantic BaseModel subclass")
        if value.model_config.get("extra") != "forbid":
            raise ValueError(f"{value.__name__} must set extra='forbid' so typos are errors")
        return value

    def content_dict(self) -> dict[str, Any]:
        """Behaviour-defining fields plus the factory's name and the parameters' schema."""
        data = super().content_dict()
        data["factory"] = f"{self.factory.__module__}:{self.factory.__qualname__}"
        data["params"] = json.loads(_schema_text(self.params))  # a fresh copy: callers edit it
        return data


@lru_cache(maxsize=256)
def _schema_text(params: type[BaseModel]) -> str:
    """The JSON schema of a parameter model, built once per class (about a millisecond each
    time, and a sensor's hash asks for it per stage, per chain compiled)."""
    return json.dumps(params.model_json_schema())
