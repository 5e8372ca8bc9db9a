"""Well-known rackets from their published spec sheets, each number with its source.

Every entry holds the keyword arguments of :func:`racket.specs.from_specs` and, for each, where
it comes from.  Two numbers are not on the sheets as the model needs them:

* the frame stiffness: each sheet gives its published RA (``ra``), turned into the first
  free-free frequency by the TWU regression (:mod:`racket.specs.ra`: 150, 157 and 154 Hz for
  RA 66, 69 and 68, each +/- 6 Hz), so that a comparison of rackets keeps their main
  difference (before the regression every entry assumed :data:`ASSUMED_F1`).
* ``tension_lb``: a racket is strung to the player's taste; 55 lb is the paper's "typical of
  most rackets" (Sec. VIII).

Nor what a racket is strung with: each entry's :attr:`Entry.strung` is **an assumption**,
fresh polyester 16L (the commonest string of the TWU string database: 406 polyesters against
213 nylons and 15 guts) at the sheet's tension, in the racket's own pattern (TWU's racquet table,
``String Pattern``), so that a catalogue racket has a real string bed (its stretch and loss,
:mod:`racket.strings.stringing`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from racket.racket import Racket
from racket.specs.fit import from_specs
from racket.specs.mass_fit import fit_key, fit_masses
from racket.specs.parts import layout
from racket.specs.sheet import spec_sheet
from racket.specs.strung import STRUNG, STRUNG_SOURCES

ASSUMED_F1 = 150.0
"""First free-free frequency [Hz] assumed where a sheet gives no frame stiffness (the
catalogue's entries did before the RA regression; the tests' sample sheets still do).
Composite rackets made after 1980 ring higher than the wooden rackets before 1970, which
were "typically characterised by ... natural frequencies below 120 Hz" (L. Taraborrelli et
al., "Materials have driven the historical development of the tennis racket", Appl. Sci. 9,
4352, 2019); the paper's 1990s graphite racket is at 120 Hz.  150 Hz is an assumption, not
a measurement of these models."""

_RECORDED = (
    "the RA published with this sheet, recorded when the entry was made (the line of the page "
    "was not quoted: unverified)"
)
PAPER_TENSION = "the paper, Sec. VIII: 55 lb is typical of most rackets"
_TWU_PATTERN = "TWU racquet table (tests/data/twu_racquets_half.csv), String Pattern of the {}"

OUNCE = 0.028349523125
"""One ounce [kg] (US spec sheets quote strung weight in oz)."""


@dataclass(frozen=True)
class Entry:
    """A catalogue racket: its name, spec-sheet keywords and their sources.

    Parameters
    ----------
    name : str
        The racket's maker and model, as printed.
    specs : dict
        Keyword arguments of :func:`racket.specs.from_specs` (their units are in their
        names, e.g. ``mass_kg``).
    sources : dict
        Where each of ``specs`` comes from, by the same keywords.
    notes : str, optional
        Remarks on the numbers.
    strung : dict, optional
        The string keywords of :func:`racket.specs.from_specs` (``string``, ``gauge``,
        ``pattern``): what the racket is strung with; default :data:`STRUNG`.
    strung_sources : dict, optional
        Where each of ``strung`` comes from, by the same keywords.
    """

    name: str
    specs: dict
    sources: dict
    notes: str = ""
    strung: dict = field(default_factory=lambda: dict(STRUNG))
    strung_sources: dict = field(default_factory=lambda: dict(STRUNG_SOURCES))

    def racket(self, support: str = "free") -> Racket:
        """The fitted racket, strung with :attr:`strung` (see
        :func:`racket.specs.from_specs`).

        Parameters
        ----------
        support : str, optional
            ``"free"``, ``"clamped-head"`` or ``"hand-held"``, as for :class:`~racket.Racket`.
        """
        return from_specs(support=support, **self.specs, **self.strung)


_TENNISADDICT = (
    "tennisaddict.fr, 'BABOLAT Pure Drive 2020 / 2021' test (8 Sept 2020), measured strung"
)
_TENNIS_COM = "tennis.com, 'Racquet review: Babolat Pure Drive' (2025), strung values"
_TENNIS_EXPRESS = "tennisexpress.com, 'Wilson Pro Staff 97L CV tennis racquet review'"


def _sheet(**quoted) -> dict:
    """An :class:`Entry`'s ``specs`` and ``sources`` from pairs (the number, where it comes
    from), one keyword of :func:`racket.specs.from_specs` each, so that every number sits
    beside its source.
    """
    return dict(
        specs={key: number for key, (number, _) in quoted.items()},
        sources={key: source for key, (_, source) in quoted.items()},
    )


CATALOG = {
    "pure-drive-2021": Entry(
        name="Babolat Pure Drive (2021)",
        **_sheet(
            length_m=(
                0.6858,
                "27 in, the standard length; Pure Drive: tennis.com review (Length 27 in)",
            ),
            mass_kg=(0.321, _TENNISADDICT + ": masse 321 g"),
            balance_cm=(33.0, _TENNISADDICT + ": equilibre 330 mm"),
            swingweight_kgcm2=(325.0, _TENNISADDICT + ": inertie 325"),
            head_size_cm2=(645.0, _TENNISADDICT + ": tamis 645 cm2"),
            ra=(66.0, _TENNISADDICT + ": RA 66 strung (68 unstrung)"),
            tension_lb=(55.0, PAPER_TENSION),
        ),
        notes="RA 66 strung (68 unstrung) measured by tennisaddict.fr; Babolat quotes 72.",
        strung_sources=STRUNG_SOURCES
        | dict(pattern=_TWU_PATTERN.format("Babolat Pure Drive (2021): 16x19")),
    ),
    "pure-drive-2025": Entry(
        name="Babolat Pure Drive (2025)",
        **_sheet(
            length_m=(0.6858, _TENNIS_COM + ": Length 27 in"),
            mass_kg=(11.1 * OUNCE, _TENNIS_COM + ": Weight 11.1 oz"),
            balance_pts_hl=(4.0, _TENNIS_COM + ": Balance 4 pts HL"),
            swingweight_kgcm2=(315.0, _TENNIS_COM + ": Swingweight 315"),
            head_size_in2=(100.0, _TENNIS_COM + ": Head Size 100 sq. in."),
            ra=(69.0, _RECORDED),
            tension_lb=(55.0, PAPER_TENSION),
        ),
        strung_sources=STRUNG_SOURCES
        | dict(pattern=_TWU_PATTERN.format("Pure Drives (2012-2021, every one 16x19)")),
    ),
    "pro-staff-97l-cv": Entry(
        name="Wilson Pro Staff 97L CV",
        **_sheet(
            length_m=(0.6858, _TENNIS_EXPRESS + ": Length 27 inches"),
            mass_kg=(10.7 * OUNCE, _TENNIS_EXPRESS + ": Weight strung 10.7 oz"),
            balance_pts_hl=(6.0, _TENNIS_EXPRESS + ": Balance 6 Pts Head Light"),
            swingweight_kgcm2=(313.0, _TENNIS_EXPRESS + ": Swing Weight 313"),
            head_size_in2=(97.0, _TENNIS_EXPRESS + ": Head Size 97 sq. in."),
            ra=(68.0, _RECORDED),
            tension_lb=(55.0, PAPER_TENSION),
        ),
        strung_sources=STRUNG_SOURCES
        | dict(pattern=_TWU_PATTERN.format("Wilson Pro Staff 97L Countervail CAMO: 16x19")),
    ),
}
"""Catalogue rackets by preset name."""


def catalogue_fits() -> dict:
    """The part-mass fit of every sheet of :data:`CATALOG`, fitted afresh
    (:func:`racket.specs.mass_fit.fit_masses`, with scipy), keyed as the record of fits
    keeps them: what :data:`racket.specs.fitted.FITTED` must hold (the same keys, the masses
    to 1e-12: their last bits follow the machine), and how it is made.
    """
    fits = {}
    for name, entry in CATALOG.items():
        sheet = spec_sheet(**entry.specs)
        lay = layout(sheet.length, sheet.head_area)
        given = (lay, sheet.mass, sheet.balance, sheet.swingweight, sheet.twistweight)
        fit = fit_masses(*given, recorded=False)
        fits[fit_key(*given)] = (name, tuple(fit.masses.tolist()), fit.twistweight_residual)
    return fits
