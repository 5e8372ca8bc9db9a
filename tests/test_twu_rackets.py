"""Rackets measured by Tennis Warehouse University fit their mass, balance, swingweight and
frequency, or are refused with a named reason; the mass model predicts their twistweight
(issue 25).  On a sample of the table (tests/data/twu_sample.csv, see data/README.md); the
full table's numbers come from ``python -m studies.twu``."""

from pathlib import Path

import pandas as pd
import pytest

from studies.twu import EXACT, REASONS, fit_table

SAMPLE = Path(__file__).parent / "data" / "twu_sample.csv"


@pytest.fixture(scope="module")
def result():
    return fit_table(pd.read_csv(SAMPLE, index_col="row"))


def test_every_sampled_racket_fits_or_is_refused_with_a_named_reason(result):
    fitted = result[result.status == "fit"]
    refused = result[result.status == "refused"]
    print(
        f"\n{len(fitted)} of {len(result)} sampled TWU rackets fit; refused "
        f"{len(refused) / len(result):.1%}: {refused.reason.value_counts().to_dict()} "
        f"(full table: 618 fit, 4 refused, 0.6 %)"
    )
    assert len(fitted) + len(refused) == len(result)
    assert (fitted.worst_relative_miss < EXACT).all()
    assert refused.reason.isin(REASONS.values()).all()
    # Independent of the fit: a racket's recoil weight is 1.21 +/- 0.08 times a uniform
    # rod's over the whole table; the refused sheets are exactly those more than 4 standard
    # deviations off it (0.77, 1.56, 1.57, 1.83), and the table's only other row beyond
    # 3 (the Head Graphene Instinct PWR, 0.92) fits since the handle may weigh 30 g.
    outliers = (result.recoil_to_rod - 1.21).abs() > 4 * 0.08
    assert list(refused.index) == list(result.index[outliers])
    assert list(refused.index) == [141, 206, 265, 412]


def test_twistweight_predicted_without_it_is_unbiased(result):
    # Full table (618 rows): predicted minus measured, median +0.12 kg cm^2, 90 % within
    # 1.66; this sample, weighted to the extremes: +0.18 and 2.21.  The median bound is the
    # sample's +/- 0.37: the hoop's centre line 2 mm further out or in (FRAME_INSET 10 or
    # 6 mm instead of 8) moves it to +0.71 or -0.32 and fails.
    error = result.twistweight_error_kgcm2.dropna()
    assert len(error) == (result.status == "fit").sum()
    assert -0.2 < error.median() < 0.55
    assert error.abs().quantile(0.9) < 2.5


def test_a_given_twistweight_is_met_where_the_parts_allow(result):
    miss = result.twistweight_given_miss_kgcm2.dropna()
    met = miss == 0.0
    print(f"\ngiven twistweight met exactly on {met.sum()} of {len(miss)} sampled rackets")
    assert met.mean() > 0.7  # full table: 527 of 618 (85 %)
    # where it is missed, the fit comes nearer than the prediction without it
    error = result.twistweight_error_kgcm2[miss.index]
    assert (miss[~met].abs() < error[~met].abs()).all()
    assert (miss[~met] * error[~met] > 0).all()  # and from the same side
