"""Rackets from their spec sheets (kept apart from the model, as pvlib keeps datasheet
fitting in ``ivtools``).

* :mod:`~racket.specs.sheet`: the spec sheet's numbers, their units and ranges;
* :mod:`~racket.specs.parts`: the parts of a racket, where their mass sits and its plausible
  range;
* :mod:`~racket.specs.mass_fit`: the part masses that meet the sheet (constrained least
  squares), and :mod:`~racket.specs.fitted`, the record of the catalogue's fits (read, not
  fitted again);
* :mod:`~racket.specs.stiffness`: the bending-stiffness profile and the flex test;
* :mod:`~racket.specs.ra`: the first free frequency from the RA rating (a regression on 622
  measured rackets);
* :mod:`~racket.specs.restring`: a racket restrung at another tension (the bed's stiffness
  from the tension is the string room's, :mod:`racket.strings.tension`);
* :mod:`~racket.specs.fit`: the fitted beam and :func:`from_specs`;
* :mod:`~racket.specs.catalog`: well-known rackets with sourced sheets.
"""

from racket.specs.fit import Profile, fit_profile, from_specs
from racket.specs.parts import PARTS
from racket.specs.ra import f1_from_ra, fit_ra_regression
from racket.specs.sheet import SPEC_RANGES, SpecSheet, spec_sheet
from racket.specs.stiffness import flex_test_stiffness

__all__ = [
    "PARTS",
    "SPEC_RANGES",
    "Profile",
    "SpecSheet",
    "f1_from_ra",
    "fit_profile",
    "fit_ra_regression",
    "flex_test_stiffness",
    "from_specs",
    "spec_sheet",
]
