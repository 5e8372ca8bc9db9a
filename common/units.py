"""Unit conversions for the units tennis people type (the core works in SI)."""

MPH = 0.44704
"""One mile per hour [m/s]."""

LB = 4.4482216152605
"""One pound-force [N] (string tensions are quoted in lb)."""

INCH = 0.0254
"""One inch [m] (lengths are quoted in inches)."""

IN2 = 0.00064516
"""One square inch [m^2] (head sizes are quoted in in^2)."""

POINT = 0.003175
"""One balance point, 1/8 in [m] (balance is quoted in points head-light)."""

GRAVITY = 9.80665
"""Standard gravity [m/s^2] (accelerations are quoted in g; the ITF's 8.165 kg deformation
load is 80.07 N with it)."""

KP_PER_CM = 100.0 * GRAVITY
"""One kilopond per centimetre [N/m]: 980.665 N/m (1 kp = 1 kgf = 9.80665 N, the standard
gravity's weight of 1 kg).  The ERT's "dynamic tension" (DT), a string bed's stiffness, is
quoted in kp/cm."""

OUNCE = 0.028349523125
"""One ounce (avoirdupois) [kg] (racket weights are quoted in oz)."""

KMH = 1.0 / 3.6
"""One kilometre per hour [m/s] (speeds are quoted in km/h outside the US and the UK)."""

SPEED_UNITS = {"m/s": 1.0, "mph": MPH, "km/h": KMH}
"""The size [m/s] of each unit a speed may be typed and shown in, by its symbol."""

SPEED_SUFFIXES = {"m/s": "m_s", "mph": "mph", "km/h": "kmh"}
"""The suffix of a column of speeds in each unit of :data:`SPEED_UNITS`
(``exit_speed_m_s``, ``exit_speed_mph``, ``exit_speed_kmh``)."""
