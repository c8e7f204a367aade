"""quadmc.integrand: a catalogue family built from keywords as a scene builds it, called on an
(n, s) array through the library's batch evaluate. Values are checked against the formulas of
functions/catalogue.cpp computed here with Python's math, to a few ulp: the batch path takes
exp and cos from glibc's libmvec, within 5 ulp of scalar glibc (README, The library)."""
import math

import numpy as np
import pytest

import quadmc

EPS = np.finfo(np.float64).eps
A, U = [2.0, 0.5, 1.25], [0.3, 0.6, 0.9]


@pytest.fixture(scope="module")
def x():
    # 1000 rows: four batches of 256 and a partial one.
    return quadmc.points("sobol", 1000, 3, seed=5, randomization="owen", allow_any_n=True)


def check(f, x, formula, tolerance):
    y = f(x)
    assert y.shape == (len(x),) and y.dtype == np.float64
    for i, point in enumerate(x):
        expected = formula(point)
        assert abs(y[i] - expected) <= tolerance(point, expected), (f.name, i, point, y[i])


def test_genz_gaussian_is_its_formula_with_its_closed_form(x):
    f = quadmc.integrand("genz_gaussian", s=3, a=A, u=U)
    assert (f.name, f.dimension, f.smoothness) == ("genz_gaussian", 3, "analytic")
    check(f, x, lambda p: math.exp(-sum(a * a * (v - u) ** 2 for a, v, u in zip(A, p, U))),
          lambda p, e: 8 * EPS * e)
    # ∫ = Π √π/(2aᵢ)[erf(aᵢ(1 − uᵢ)) + erf(aᵢuᵢ)] (functions/genz.hpp).
    exact = math.prod(math.sqrt(math.pi) / (2 * a) * (math.erf(a * (1 - u)) + math.erf(a * u))
                      for a, u in zip(A, U))
    assert abs(f.exact - exact) <= 16 * EPS * exact


def test_genz_oscillatory_and_continuous_are_their_formulas(x):
    f = quadmc.integrand("genz_oscillatory", s=3, a=A, u=U)
    angle = lambda p: 2 * math.pi * U[0] + sum(a * v for a, v in zip(A, p))
    # cos near its zeros: an absolute bound, ε times the argument's size.
    check(f, x, lambda p: math.cos(angle(p)), lambda p, e: 8 * EPS * (1 + abs(angle(p))))
    g = quadmc.integrand("genz_continuous", s=3, a=A, u=U)
    assert g.smoothness == "C0"
    check(g, x, lambda p: math.exp(-sum(a * abs(v - u) for a, v, u in zip(A, p, U))),
          lambda p, e: 8 * EPS * e)


def test_poly_on_an_interval_and_its_domain():
    f = quadmc.integrand("poly", lower=-1, upper=2)
    assert f.dimension == 1 and f.domain == [(-1.0, 2.0)]
    assert abs(f.exact - 63 / 6) <= 4 * EPS * 10.5  # ∫ x⁵ over [−1, 2] = (2⁶ − 1)/6
    x = np.linspace(-1, 2, 301).reshape(-1, 1)
    np.testing.assert_allclose(f(x), x[:, 0] ** 5, rtol=4 * EPS, atol=0)


def test_drawn_parameters_follow_the_seed():
    x = quadmc.points("halton", 64, 4, seed=1)
    a = quadmc.integrand("genz_product_peak", s=4, seed=3)
    b = quadmc.integrand("genz_product_peak", s=4, seed=3)
    c = quadmc.integrand("genz_product_peak", s=4, seed=4)
    assert np.array_equal(a(x), b(x)) and a.exact == b.exact
    assert a.exact != c.exact
    assert np.isfinite(a.exact)


def test_coefficient_decay_shapes_only_the_drawn_a():
    plain = quadmc.integrand("genz_gaussian", s=4, seed=3)
    none = quadmc.integrand("genz_gaussian", s=4, seed=3, coefficient_decay="none")
    assert none.exact == plain.exact
    for decay in ("quadratic", "exponential"):
        f = quadmc.integrand("genz_gaussian", s=4, seed=3, coefficient_decay=decay)
        assert np.isfinite(f.exact) and f.exact != plain.exact, decay


@pytest.mark.parametrize("call,text", [
    (lambda: quadmc.integrand("genz_gaussian", s=2, b=[1, 2]),
     "invalid b: unknown key: not a parameter of genz_gaussian (its parameters: arrays: a, u; "
     "numbers: none; strings: coefficient_decay)"),
    (lambda: quadmc.integrand("genz_gaussian", s=2, a=2.0),
     "invalid a: expected an array of numbers for genz_gaussian, got 2"),
    (lambda: quadmc.integrand("genz_gaussian", s=2, a="ab"),
     'invalid a: expected an array of numbers for genz_gaussian, got "ab"'),
    (lambda: quadmc.integrand("genz_gaussian", s=2, a=None),
     "invalid a = None: expected a number, a non-empty sequence of numbers or a str"),
    (lambda: quadmc.integrand("genz_gaussian", s=2, coefficient_decay="cubic"),
     'invalid coefficient_decay: expected one of "none", "quadratic", "exponential", got "cubic"'),
    (lambda: quadmc.integrand("genz_gaussian", s=2, a=[1, 2], coefficient_decay="quadratic"),
     'invalid coefficient_decay = "quadratic": expected no explicit a beside it'),
    (lambda: quadmc.integrand("geometric_asian", s=4, construction="brownian"),
     'invalid construction: expected one of "standard", "bridge", "pca", got "brownian"'),
    (lambda: quadmc.integrand("geometric_asian", s=4, construction=1),
     'invalid construction: expected a string, one of "standard", "bridge", "pca", for '
     "geometric_asian, got 1"),
    (lambda: quadmc.integrand("genz_gaussian", s=0), "invalid s = 0: expected an integer in [1, "),
    (lambda: quadmc.integrand("genz_gaussian", s=2)(np.zeros((4, 3))),
     "invalid x = an array of shape (4, 3): expected a 2D array of shape (n, 2) for genz_gaussian"),
])
def test_bad_input_is_a_value_error_with_the_librarys_text(call, text):
    with pytest.raises(ValueError) as error:
        call()
    assert str(error.value).startswith(text), str(error.value)


def test_an_unknown_family_names_every_family():
    with pytest.raises(ValueError) as error:
        quadmc.integrand("nope")
    names = ", ".join(f["name"] for f in quadmc.integrands())
    assert str(error.value) == f"invalid integrand = nope: expected one of {names}"
