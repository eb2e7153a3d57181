"""Built-in signal readers, one format per module, each registered through its own entry point
(``reader-<format>`` in pyproject.toml) exactly as a third party's reader plugin would be."""
