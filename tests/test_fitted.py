"""The record of fits (:mod:`racket.specs.fitted`): the catalogue's part masses, read instead
of fitted (no scipy.optimize at a catalogue racket's start), are what the fit gives, bit
for bit; a sheet whose inputs differ in any bit is fitted afresh.
"""

import numpy as np

from racket.specs.catalog import CATALOG, catalogue_fits
from racket.specs.fitted import FITTED
from racket.specs.mass_fit import fit_key, fit_masses
from racket.specs.parts import layout
from racket.specs.sheet import spec_sheet


def test_the_record_is_the_catalogues_fits_made_afresh():
    assert catalogue_fits() == FITTED
    assert sorted(name for name, _, _ in FITTED.values()) == sorted(CATALOG)


def test_a_recorded_fit_is_read_and_a_changed_sheet_is_fitted():
    sheet = spec_sheet(**CATALOG["pure-drive-2021"].specs)
    given = [layout(sheet.length, sheet.head_area), sheet.mass, sheet.balance, sheet.swingweight]
    read, fitted = fit_masses(*given), fit_masses(*given, recorded=False)
    assert read.masses.tobytes() == fitted.masses.tobytes()
    assert read.twistweight_residual == fitted.twistweight_residual
    assert fit_key(*given) in FITTED
    given[1] = np.nextafter(given[1], 1.0)  # one bit more mass: no record
    assert fit_key(*given) not in FITTED
    assert fit_masses(*given).masses.sum() == fit_masses(*given, recorded=False).masses.sum()
