"""The record of fits (:mod:`racket.specs.fitted`): the catalogue's part masses, read instead
of fitted (no scipy.optimize at a catalogue racket's start), are what the fit gives (to
1e-12: the fit's last bits follow the machine's BLAS and maths library), keyed alike on every
machine; a sheet whose inputs differ beyond the key's ten digits is fitted afresh.
"""

import numpy as np
import pytest

from racket.specs.catalog import CATALOG, catalogue_fits
from racket.specs.fitted import FITTED
from racket.specs.mass_fit import KEY_DIGITS, _key, _problem, fit_key, fit_masses, typical_split
from racket.specs.parts import layout
from racket.specs.sheet import spec_sheet


def _given(name="pure-drive-2021"):
    sheet = spec_sheet(**CATALOG[name].specs)
    given = [layout(sheet.length, sheet.head_area), sheet.mass, sheet.balance, sheet.swingweight]
    return given, sheet.twistweight


def test_the_record_is_the_catalogues_fits_made_afresh():
    fresh = catalogue_fits()
    assert sorted(fresh) == sorted(FITTED)
    for key, (name, masses, residual) in fresh.items():
        assert FITTED[key][0] == name
        assert FITTED[key][1] == pytest.approx(masses, rel=1e-12, abs=0.0)
        assert FITTED[key][2] == (None if residual is None else pytest.approx(residual))
    assert sorted(name for name, _, _ in FITTED.values()) == sorted(CATALOG)


def test_a_recorded_fit_is_read_and_a_changed_sheet_is_fitted():
    given, _ = _given()  # (no twistweight: the default racket's sheet gives none)
    read, fitted = fit_masses(*given), fit_masses(*given, recorded=False)
    assert read.masses == pytest.approx(fitted.masses, rel=1e-12, abs=0.0)
    assert read.twistweight_residual == fitted.twistweight_residual
    assert fit_key(*given) in FITTED
    given[1] *= 1.0 + 10.0 ** (1 - KEY_DIGITS)  # the mass changed in its tenth digit: no record
    assert fit_key(*given) not in FITTED
    assert fit_masses(*given).masses.sum() == fit_masses(*given, recorded=False).masses.sum()


@pytest.mark.parametrize("name", sorted(CATALOG))
def test_the_key_does_not_follow_the_machines_last_bits(name):
    """Every input a few units in the last place away, as another machine's BLAS and maths
    library make them: the same key, the same record read."""
    (lay, mass, balance, swingweight), twistweight = _given(name)
    _, moments, target = _problem(lay, mass, balance, swingweight)
    typical = typical_split(mass)
    key = _key(moments, target, typical, twistweight)
    assert key in FITTED
    for ulps in (-3, 3):
        nudged = [
            np.asarray(a, dtype=float) + ulps * np.spacing(a) for a in (moments, target, typical)
        ]
        assert _key(*nudged, twistweight) == key
