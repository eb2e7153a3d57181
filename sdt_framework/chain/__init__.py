"""The Sensor Digital Twin measurement chain (SPEC section 2)."""
