"""The record of fits: the part masses of the catalogue's sheets
(:data:`racket.specs.catalog.CATALOG`) as :func:`racket.specs.mass_fit.fit_masses` fits them,
so that a process building a catalogue racket reads them instead of importing
:mod:`scipy.optimize` to fit them again.

Each fit is keyed by a digest of every input of the fit (:func:`racket.specs.mass_fit.fit_key`):
a sheet that is not here, or whose inputs have changed in any bit (a part's range, the
layout), is fitted afresh.  Made by :func:`racket.specs.catalog.catalogue_fits`, which fits
every sheet of the catalogue afresh (printed, then ``ruff format``); ``tests/test_fitted.py``
checks that this record is what it returns, bit for bit.
"""

FITTED = {
    "7c49a409db3070645af32f09e1abb2aef0d45d65380bb49306ce85322fb17d1b": (
        "pure-drive-2021",
        (
            0.00944990501751504,
            0.13756925170191175,
            0.01603053299840875,
            0.038804754323243915,
            0.10452647795810152,
            0.01461907800081903,
        ),
        None,
    ),
    "520c6fe53d9ff47f0b96f42a86bc87d28a0ecae0b16bcf1cc69e26579d5c2cd7": (
        "pure-drive-2025",
        (
            0.00858945619767454,
            0.1326714743220317,
            0.016034301779670124,
            0.045132572983898854,
            0.09845178858350406,
            0.013800112820720713,
        ),
        None,
    ),
    "e1193b2427e3408888811a1b50e52c1af86e9a273ae482b52d9789e99e3268ac": (
        "pro-staff-97l-cv",
        (
            0.01193563670047507,
            0.12911072072890692,
            0.01596038435980319,
            0.015,
            0.11375303678535253,
            0.017580118862962287,
        ),
        None,
    ),
}
"""Key (:func:`racket.specs.mass_fit.fit_key`) -> (the catalogue's name of the sheet; the
part masses [kg], in the order of :data:`racket.specs.parts.PARTS`; the twistweight residual
[kg m^2] or None)."""
