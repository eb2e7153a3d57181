"""ClassifierSpec: a scikit-learn-compatible estimator named by import path."""

from __future__ import annotations

import importlib
import re
from typing import Any, ClassVar

from pydantic import Field, field_validator

from .base import Spec

__all__ = ["ClassifierSpec"]


class ClassifierSpec(Spec):
    """A scikit-learn-compatible classifier with fixed hyperparameters.

    ``estimator`` is an import path ``"module:Class"``, imported only when an
    estimator is built, so listing classifiers stays fast.
    """

    kind: ClassVar[str] = "classifier"

    estimator: str = Field(description="Import path 'package.module:ClassName'.")
    params: dict[str, Any] = Field(default_factory=dict, description="Hyperparameters.")
    seed_param: str | None = Field(
        default="random_state",
        description="Constructor argument that takes the seed; None if deterministic.",
    )

    @field_validator("estimator")
    @classmethod
    def _check_path(cls, value: str) -> str:
        if not re.match(r"^[A-Za-z_][\w.]*:[A-Za-z_]\w*$", value):
            raise ValueError(f"{value!r} is not an import path of the form 'module:Class'")
        return value

    def estimator_class(self) -> type:
        """Import and return the estimator class."""
        module, _, attr = self.estimator.partition(":")
        try:
            return getattr(importlib.import_module(module), attr)
        except (ImportError, AttributeError) as exc:
            from ..errors import SDTError

            raise SDTError(
                f"classifier {self.name!r}: cannot import {self.estimator} ({exc}); "
                f"install the package that provides it"
            ) from exc

    def build(self, seed: int | None = None) -> Any:
        """A fresh, unfitted estimator; ``seed`` goes to ``seed_param`` if set."""
        kwargs = dict(self.params)
        if self.seed_param is not None and seed is not None:
            kwargs[self.seed_param] = seed
        return self.estimator_class()(**kwargs)
