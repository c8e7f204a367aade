"""quadmc.discrepancy against closed forms (sampling/discrepancy.hpp states the three formulas;
docs/theory.md#discrepancy derives them). Tolerances are on D² in multiples of the machine
epsilon times the size of the terms the formula subtracts."""
import math

import numpy as np
import pytest

import quadmc

EPS = np.finfo(np.float64).eps


def one_point_squares(x):
    """D*², CD², WD² of the single point x, from the formulas with N = 1 (the pair sum is the
    point with itself), and the size of the largest term each subtracts."""
    s = len(x)
    star = (3.0 ** -s - 2.0 ** (1 - s) * math.prod(1 - v * v for v in x)
            + math.prod(1 - v for v in x))
    d = [abs(v - 0.5) for v in x]
    centered = ((13 / 12) ** s - 2 * math.prod(1 + a / 2 - a * a / 2 for a in d)
                + math.prod(1 + a for a in d))
    wrap = -(4 / 3) ** s + 1.5 ** s
    return {"l2_star": (star, 2.0), "centered": (centered, 2 * (13 / 12) ** s + 1.5 ** s),
            "wrap_around": (wrap, 1.5 ** s)}


@pytest.mark.parametrize("x", [[0.3], [0.25, 0.75], [0.1, 0.9, 0.5, 0.0], [1.0, 0.2, 0.6]])
@pytest.mark.parametrize("kind", ["l2_star", "centered", "wrap_around"])
def test_one_point_has_the_closed_form(x, kind):
    square, scale = one_point_squares(x)[kind]
    got = quadmc.discrepancy(np.array([x]), kind)
    assert abs(got * got - square) <= 16 * EPS * scale, (x, kind, got, math.sqrt(square))


@pytest.mark.parametrize("n", [1, 7, 64, 1000])
def test_midpoints_in_1d_have_d_star_squared_1_over_12_n_squared(n):
    # D*² of the midpoints (i + ½)/N in 1D is 1/(12N²), the smallest of any N points.
    x = ((np.arange(n) + 0.5) / n).reshape(n, 1)
    got = quadmc.discrepancy(x, "l2_star")
    # The formula subtracts sums of N and N² terms of size ≤ 1: rounding of order N·ε at most.
    assert abs(got * got - 1 / (12 * n * n)) <= 8 * n * EPS, (n, got)


def test_any_layout_and_dtype_give_the_same_value():
    x = quadmc.points("halton", 100, 3, seed=4)
    expected = quadmc.discrepancy(x, "centered")
    assert quadmc.discrepancy(np.asfortranarray(x), "centered") == expected
    assert quadmc.discrepancy(x.tolist(), "centered") == expected
    wide = np.zeros((100, 6))
    wide[:, ::2] = x
    assert quadmc.discrepancy(wide[:, ::2], "centered") == expected  # a strided view


def test_a_shifted_lattice_has_its_lattices_wrap_around_discrepancy():
    # The wrap-around discrepancy is invariant under shifts modulo 1 (sampling/discrepancy.hpp).
    plain = quadmc.points("lattice", 64, 2, randomization="none")
    shifted = quadmc.points("lattice", 64, 2, seed=3, randomization="shift")
    a, b = quadmc.discrepancy(plain, "wrap_around"), quadmc.discrepancy(shifted, "wrap_around")
    assert abs(a * a - b * b) <= 64 * EPS * 1.5 ** 2


@pytest.mark.parametrize("points,kind,start", [
    (np.zeros((4, 2)), "star", "invalid kind = star: expected one of l2_star, centered, wrap_around"),
    (np.zeros(4), "l2_star", "invalid points = an array of shape (4): expected a 2D array"),
    (np.zeros((0, 2)), "l2_star", "invalid points = an array of shape (0, 2): "),
    (np.zeros((2 ** 14 + 1, 1)), "l2_star", "invalid points = an array of shape (16385, 1): "),
    (np.array([[0.5, 1.5]]), "centered", "invalid points[0, 1] = 1.5: expected a coordinate"),
    (np.array([[0.5], [math.nan]]), "wrap_around", "invalid points[1, 0] = nan: "),
])
def test_bad_input_is_a_value_error_naming_the_parameter(points, kind, start):
    with pytest.raises(ValueError) as error:
        quadmc.discrepancy(points, kind)
    assert str(error.value).startswith(start), str(error.value)
