"""Unit conversions for the units tennis people type (the core works in SI)."""

MPH = 0.44704
"""One mile per hour [m/s]."""
