"""Real roots of Bernstein-form polynomials (notes ch. 9): accuracy, edge cases, bad input."""

import numpy as np
import pytest
from numpy.polynomial import polynomial as P

from cagd_ref import roots
from cagd_ref.polynomials import bernstein_multiply, bernstein_to_power, power_to_bernstein
from cagd_ref.roots import bernstein_roots, hull_crossing


def test_public_names_are_all_tested():
    assert set(roots.__all__) == {"bernstein_roots", "hull_crossing"}


def _from_roots(rs):
    """Bernstein coefficients on [0, 1] of Π (t - r), built stably factor by factor."""
    coeffs = np.array([1.0])
    for r in rs:
        coeffs = bernstein_multiply(coeffs, np.array([-r, 1 - r]))
    return coeffs


@pytest.mark.parametrize("degree", [5, 10, 20])
def test_wilkinson_type_roots_are_found_far_more_accurately_than_from_the_power_form(degree):
    exact = np.arange(1, degree + 1) / (degree + 1)
    found = bernstein_roots(_from_roots(exact))
    ours = np.abs(found - exact).max()
    power = np.sort(np.roots(P.polyfromroots(exact)[::-1]).real)
    theirs = np.abs(power - exact).max()
    assert len(found) == degree and ours < 1e-9
    if degree >= 10:
        assert ours * 100 < theirs


def test_random_polynomials_agree_with_numpy_on_well_separated_roots():
    rng = np.random.default_rng(9)
    for _ in range(20):
        inside = np.sort(rng.choice(np.linspace(0.05, 0.95, 19), size=3, replace=False))
        outside = rng.uniform(1.5, 3.0, size=2) * rng.choice([-1, 1], size=2)
        coeffs = power_to_bernstein(P.polyfromroots(np.concatenate([inside, outside])))
        np.testing.assert_allclose(bernstein_roots(coeffs), inside, atol=1e-10)


def test_interval_maps_the_roots():
    # (t - 2.5)(t - 3.5) on [2, 4]: local roots 0.25, 0.75.
    coeffs = _from_roots([0.25, 0.75])
    np.testing.assert_allclose(bernstein_roots(coeffs, interval=(2, 4)), [2.5, 3.5], atol=1e-12)


@pytest.mark.parametrize(
    "coeffs, expected",
    [([1.0, -1.0], [0.5]), ([0.0, 1.0, 2.0], [0.0]), ([2.0, 1.0, 0.0], [1.0]), ([1.0, 2.0, 3.0], []), ([3.0], [])],
)
def test_edge_cases(coeffs, expected):
    np.testing.assert_allclose(bernstein_roots(coeffs), expected, atol=1e-12)


def test_a_double_root_is_located_to_the_square_root_of_precision():
    found = bernstein_roots(_from_roots([0.3, 0.3, 0.7]))
    assert np.isclose(found[-1], 0.7, atol=1e-12)
    assert 1 <= len(found) - 1 <= 2 and np.allclose(found[:-1], 0.3, atol=1e-7)


def test_hull_crossing_bounds_every_root_and_rejects_one_signed_polygons():
    coeffs = _from_roots([0.4, 0.6])
    lo, hi = hull_crossing(coeffs)
    assert lo <= 0.4 and hi >= 0.6 and 0 <= lo < hi <= 1
    assert hull_crossing([1.0, 0.5, 2.0]) is None
    assert hull_crossing([0.0]) == (0.0, 1.0) and hull_crossing([1.0]) is None


def test_roots_are_roots_of_the_power_form_too():
    coeffs = np.array([2.0, -3.0, 4.0, -1.0, 0.5])
    for r in bernstein_roots(coeffs):
        assert abs(P.polyval(r, bernstein_to_power(coeffs))) < 1e-12


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"coeffs": [0.0, 0.0]}, "coeffs"),
        ({"coeffs": [[1.0, 2.0]]}, "coeffs"),
        ({"coeffs": [1.0, np.nan]}, "coeffs"),
        ({"coeffs": [1.0, -1.0], "interval": (1, 0)}, "interval"),
        ({"coeffs": [1.0, -1.0], "tol": 0.0}, "tol"),
    ],
)
def test_bad_input_is_rejected_with_the_argument_named(kwargs, match):
    with pytest.raises((ValueError, TypeError), match=match):
        bernstein_roots(**kwargs)


def test_input_is_not_modified():
    coeffs = np.array([1.0, -2.0, 0.5])
    bernstein_roots(coeffs)
    assert coeffs.tolist() == [1.0, -2.0, 0.5]
