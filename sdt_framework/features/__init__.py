"""Windowing and feature extraction (SPEC section 3)."""
