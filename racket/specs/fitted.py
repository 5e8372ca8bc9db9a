"""The record of fits: the part masses of the catalogue's sheets
(:data:`racket.specs.catalog.CATALOG`) as :func:`racket.specs.mass_fit.fit_masses` fits them,
so that a process building a catalogue racket reads them instead of importing
:mod:`scipy.optimize` to fit them again.

Each fit is keyed by a digest of every input of the fit to ten significant digits
(:func:`racket.specs.mass_fit.fit_key`, :data:`racket.specs.mass_fit.KEY_DIGITS`): a sheet
that is not here, or whose inputs have changed (a part's range, the layout), is fitted
afresh.  Made by :func:`racket.specs.catalog.catalogue_fits`, which fits every sheet of the
catalogue afresh (printed, then ``ruff format``); ``tests/test_fitted.py`` checks that this
record is what it returns: the same keys, and masses within 1e-12 of the fit's (their last
bits are those of the machine that recorded them, as the fit's own last bits follow the
machine's BLAS and maths library).
"""

FITTED = {
    "0738d633d2b020931536c6a4747cd8dda8fbf103165f5c2324a5dc0ab941141a": (
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
    "14a458834dffde2aa7b973f591a5308c34adcc23311f7d2d5ce80f46752ed103": (
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
    "5ce7f7d04d877f3c3e970c128ef37e2dcbe5a885f31348c399cf75c478b95012": (
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
