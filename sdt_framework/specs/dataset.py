"""DatasetSpec: a source of recordings, loaded by a plugin's loader function."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, ClassVar

from pydantic import Field

from .base import Spec

__all__ = ["DatasetSpec"]


class DatasetSpec(Spec):
    """A source of recordings.

    ``loader(path, **options)`` returns a dataset object (see
    ``sdt_framework.data``). ``requires_path`` is False for generated data.
    A loader that reads signal files through the registered readers (a
    manifest) sets ``reads_signal_files``: its caller hands the readers down as
    ``readers=`` (``sdt_framework.data.open.load_dataset``), never the loader
    looks them up.
    """

    kind: ClassVar[str] = "dataset"
    _provenance: ClassVar[frozenset[str]] = frozenset({"plugin", "distribution", "loader"})

    loader: Callable[..., Any] = Field(exclude=True, description="loader(path, **options).")
    requires_path: bool = Field(default=True, description="Whether a path must be given.")
    reads_signal_files: bool = Field(
        default=False,
        description="Whether the loader takes the registered signal readers as ``readers=``.",
    )

    def content_dict(self) -> dict[str, Any]:
        """Behaviour-defining fields plus the loader's qualified name."""
        data = super().content_dict()
        data["loader"] = f"{self.loader.__module__}:{self.loader.__qualname__}"
        return data
