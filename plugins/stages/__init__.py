"""Built-in chain stages: the error terms datasheets specify (registered like any plugin)."""
