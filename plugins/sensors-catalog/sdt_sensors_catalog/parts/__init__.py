"""One TOML file per part (package data); see docs/sensors.md for the format."""
