"""Bat studies (issue 37), the answers of ``racket-impact bat``.

* :mod:`~studies.bat.sweep`: the exit speed along the barrel, its peak and the sweet zone,
  and what every bat answer shares (the default pitch and swing, the bat by name, its
  conditions line);
* :mod:`~studies.bat.certification`: BBCOR, BESR and BPF of a pivoted bat;
* :mod:`~studies.bat.feel`: what reaches the hands;
* :mod:`~studies.bat.config`: a bat of one's own from TOML.

The bats themselves are in :mod:`bat`.
"""
