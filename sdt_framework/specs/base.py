"""The common base of every spec: a unique name, a description, provenance, a content hash.

Specs are frozen and reject unknown fields, so a typo in a TOML sensor file or
a plugin is an error rather than a silently ignored setting. Each spec carries
``plugin`` and ``distribution`` provenance (stamped by the registry, excluded
from the content hash) and a ``source`` reference (datasheet, paper, URL).
"""

from __future__ import annotations

import hashlib
import json
import re
from typing import Any, ClassVar

from pydantic import BaseModel, ConfigDict, Field, field_validator

__all__ = ["Spec"]

_NAME = re.compile(r"^[a-z0-9][a-z0-9._-]*$")


class Spec(BaseModel):
    """Common base: a unique lower-case name, a description, provenance."""

    model_config = ConfigDict(frozen=True, extra="forbid", arbitrary_types_allowed=True)

    kind: ClassVar[str] = "spec"
    _provenance: ClassVar[frozenset[str]] = frozenset({"plugin", "distribution"})

    name: str = Field(description="Unique lower-case name used on the command line.")
    description: str = Field(default="", description="One line saying what this is.")
    source: str = Field(default="", description="Datasheet, paper or URL the values come from.")
    plugin: str | None = Field(default=None, description="Plugin that registered it (stamped).")
    distribution: str | None = Field(
        default=None, description="Installed distribution providing it (stamped)."
    )

    @field_validator("name")
    @classmethod
    def _check_name(cls, value: str) -> str:
        if not _NAME.match(value):
            raise ValueError(
                f"{value!r} is not a valid name: use lower-case letters, digits, '.', '_' or '-'"
            )
        return value

    def content_dict(self) -> dict[str, Any]:
        """The fields that define behaviour (provenance excluded), JSON-ready."""
        return self.model_dump(mode="json", exclude=set(self._provenance))

    def content_hash(self) -> str:
        """A stable SHA-256 of the behaviour-defining fields, for cache keys."""
        payload = json.dumps(
            {"kind": self.kind, **self.content_dict()}, sort_keys=True, separators=(",", ":")
        )
        return hashlib.sha256(payload.encode()).hexdigest()
