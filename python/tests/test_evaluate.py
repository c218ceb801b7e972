"""`Evaluation`'s interval is honest for small samples: one wall set gives none (it printed
"± inf" for 4 games), a few sets a Student's t interval, wider than the normal one."""

import math

import pytest

import rinshan
from rinshan.evaluate import t975


def test_t_quantiles_match_the_tables_and_approach_the_normal():
    assert t975(1) == 12.706 and t975(2) == 4.303 and t975(30) == 2.042
    # Past the table: within 1e-4 of the exact quantiles (40: 2.02108, 120: 1.97993).
    assert abs(t975(40) - 2.02108) < 1e-4 and abs(t975(120) - 1.97993) < 1e-4
    values = [t975(df) for df in range(1, 200)]
    assert all(a > b for a, b in zip(values, values[1:]))
    assert values[-1] > 1.96
    with pytest.raises(ValueError):
        t975(0)


def test_one_wall_set_gives_no_interval_and_says_so():
    r = rinshan.evaluate("random", "rule", games=4, mode="single")
    assert r.games == 4 and math.isnan(r.ci95)
    text = str(r)
    assert "n too small for an interval" in text and "inf" not in text and "nan" not in text


def test_two_wall_sets_give_a_finite_t_interval():
    r = rinshan.evaluate("random", "rule", games=8, mode="single")
    assert r.games == 8 and math.isfinite(r.ci95) and r.ci95 >= 0
    assert f"± {r.ci95:.3f}" in str(r)
