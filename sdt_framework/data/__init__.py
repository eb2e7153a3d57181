"""Datasets: recordings with metadata (SPEC section 4)."""
