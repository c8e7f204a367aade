"""quadmc.integrate: a method of the registry on a catalogue Integrand or a Python callable, run as
a scene's cell (bench/python/integrate.cpp). A numpy twin of a catalogue integrand gives the
catalogue's estimate; the same arguments give the same bits; rng names the generator of the
method's numbers as a scene's rng does; errors raised by the callable reach Python as they were
raised; bad input is ValueError with the library's one-line text."""
import math
from statistics import NormalDist

import numpy as np
import pytest

import quadmc

EPS = np.finfo(np.float64).eps
A, U = [1.0, 2.0, 0.5, 1.5], [0.3, 0.6, 0.45, 0.2]


@pytest.fixture(scope="module")
def catalogue():
    return quadmc.integrand("genz_gaussian", s=4, a=A, u=U)


def twin(x):
    """genz_gaussian as functions/genz.hpp evaluates it: e = Σ_j a_j²·d_j·d_j in order j, exp(−e)."""
    e = np.zeros(len(x))
    for a, u, column in zip(A, U, x.T):
        d = column - u
        e = e + a * a * d * d
    return np.exp(-e)


# Both runs sum the same points with the same kernel, so they differ only by the values: the
# twin's exp (numpy) and the catalogue's (libmvec) are each within a few ulp of exp, and the
# C++ sum may fuse a multiply-add; say |Δf_i| ≤ 8 ε f_i (as tests/python/test_integrand.py). With
# f > 0 the sums then differ by ≤ 8 ε Σf plus the rounding of two pairwise sums, ≤ 2 log2(N) ε Σf:
# relative (8 + 2·16) ε ≈ 9e-15 at N = 2^16, 1e-13 with margin.
RELATIVE = 1e-13


@pytest.mark.parametrize("method, n", [("plain_mc", 2**16), ("simpson", 6561)])
def test_a_numpy_twin_gives_the_catalogue_estimate(catalogue, method, n):
    expected = quadmc.integrate(catalogue, method, n, seed=3, repetitions=2)
    got = quadmc.integrate(twin, method, n, s=4, seed=3, repetitions=2, name="genz_gaussian_s4")
    assert got.method == expected.method == method and got.n == n
    assert got.evaluations == expected.evaluations
    assert len(got.values) == len(expected.values) == (2 if method == "plain_mc" else 1)
    for g, e in zip(got.values, expected.values):
        assert abs(g - e) <= RELATIVE * abs(e), (method, g, e)
    # And both are estimates of the integral: within 6 standard errors (Monte Carlo) or the
    # Simpson error at 9 nodes per axis (|error| ≈ 4e-5 here; 1e-3 bounds it).
    bound = 6 * expected.std_error if method == "plain_mc" else 1e-3
    assert abs(expected.value - catalogue.exact) <= bound


def test_a_callable_is_called_once_per_block_of_thousands_of_points():
    # The fixed-N kernels call it once per block of up to 2^14 points and 16 MiB of them, within a
    # chunk (12288 points for Monte Carlo, 16384 for a rule: lib/include/quadmc/core/batching.hpp),
    # so that Python's cost per call is paid rarely (bench/python/integrate.cpp).
    sizes = []

    def recorded(x):
        sizes.append(x.shape)
        return np.ones(len(x))

    quadmc.integrate(recorded, "plain_mc", 2**16, s=4)
    assert sizes == [(12288, 4)] * 5 + [(4096, 4)]
    sizes.clear()
    quadmc.integrate(recorded, "simpson", 6561, s=4)
    assert sizes == [(6561, 4)]
    sizes.clear()
    quadmc.integrate(recorded, "plain_mc", 10000, s=1024)  # 16 MiB: 2048 points of s = 1024
    assert sizes == [(2048, 1024)] * 4 + [(1808, 1024)]


def test_the_same_arguments_give_the_same_bits(catalogue):
    for f, s in [(catalogue, None), (twin, 4)]:
        first = quadmc.integrate(f, "plain_mc", 5000, s=s, seed=11, repetitions=3)
        again = quadmc.integrate(f, "plain_mc", 5000, s=s, seed=11, repetitions=3)
        other = quadmc.integrate(f, "plain_mc", 5000, s=s, seed=12, repetitions=3)
        assert first.values == again.values and first.value == again.value
        assert first.values != other.values
        assert len(set(first.values)) == 3  # each repetition its own stream


def test_the_thread_count_does_not_change_a_bit(catalogue):
    # 2^17 points: 11 chunks of 12288 (core/batching.hpp), so two threads share them.
    one = quadmc.integrate(catalogue, "plain_mc", 2**17, seed=5, repetitions=2, threads=1)
    two = quadmc.integrate(catalogue, "plain_mc", 2**17, seed=5, repetitions=2, threads=2)
    assert one.values == two.values and one.std_error == two.std_error


# False-alarm probability ≤ 1e-4: half of it is the two-sided normal tail beyond
# z = Φ⁻¹(1 − 5e-5/2) ≈ 4.06 standard errors; the other half is room for the standard error being
# estimated (at N = 2^16 its relative error is about 0.6 % for this bounded integrand, which moves
# the tail by about 1 %) and for the mean of 2^16 bounded values being only nearly normal. The seed
# is fixed: it had that chance of failing when chosen, and fails for good only if ARS's numbers
# or the estimate are wrong.
FALSE_ALARM = 1e-4
Z = NormalDist().inv_cdf(1 - FALSE_ALARM / 4)


def test_ars_runs_and_its_estimate_is_within_z_standard_errors(catalogue):
    # ARS-4x32-7 (docs/theory.md#counter-based-generators) drives the method's points through
    # run_context::rng; the integrand's own parameters are the same under both generators.
    ars = quadmc.integrate(catalogue, "plain_mc", 2**16, seed=17, rng="ars4x32_7")
    philox = quadmc.integrate(catalogue, "plain_mc", 2**16, seed=17)
    assert ars.evaluations == 2**16 and ars.std_error > 0
    assert abs(ars.value - catalogue.exact) <= Z * ars.std_error, (ars.value, catalogue.exact)
    assert ars.values != philox.values  # other numbers from the same seed and stream
    assert quadmc.integrate(catalogue, "plain_mc", 2**16, seed=17, rng="ars4x32_7").values == \
        ars.values
    # A callable sees the same points as the catalogue integrand under ARS too.
    twin_ars = quadmc.integrate(twin, "plain_mc", 2**16, s=4, seed=17, rng="ars4x32_7",
                                name="genz_gaussian_s4")
    assert abs(twin_ars.value - ars.value) <= RELATIVE * abs(ars.value)


def test_the_default_generator_is_philox(catalogue):
    for method in ("plain_mc", "sobol"):
        default = quadmc.integrate(catalogue, method, 1024, seed=4, repetitions=2)
        philox = quadmc.integrate(catalogue, method, 1024, seed=4, repetitions=2,
                                  rng="philox4x32_10")
        assert default.values == philox.values, method


def test_ars_gives_the_values_of_a_scene_with_rng_ars(catalogue):
    # The cell of a scene with rng = "ars4x32_7", the same seed and integrand name, one repetition:
    # its estimate_mean is the one value, written as the shortest text that reads back to it.
    scene = {"name": "ars", "seed": 9, "rng": "ars4x32_7", "threads": 1,
             "integrand": [{"family": "genz_gaussian", "dimension": 4, "a": A, "u": U}],
             "method": [{"name": "plain_mc", "repetitions": 1}],
             "budget": {"N": [4096]}, "output": {"plots": False}}
    row = quadmc.run(scene).convergence[0]
    got = quadmc.integrate(catalogue, "plain_mc", 4096, seed=9, rng="ars4x32_7")
    assert (row["integrand"], row["method"]) == ("genz_gaussian_s4", "plain_mc")
    assert got.values == [row["estimate_mean"]]


def test_the_result_folds_the_repetitions(catalogue):
    r = quadmc.integrate(catalogue, "plain_mc", 4096, seed=1, repetitions=4)
    assert r.value == math.fsum(r.values) / 4
    assert r.evaluations == 4 * 4096 and r.seconds > 0
    assert r.error_estimate == r.std_error > 0
    rule = quadmc.integrate(catalogue, "simpson", 6561, repetitions=4)
    assert len(rule.values) == 1 and math.isnan(rule.std_error)  # a rule runs once


def test_an_exception_in_the_callable_propagates_with_its_traceback():
    class Boom(Exception):
        pass

    def explodes(x):
        raise Boom(f"no value for {len(x)} points")

    with pytest.raises(Boom, match="no value for 1000 points") as raised:  # one block of all 1000
        quadmc.integrate(explodes, "plain_mc", 1000, s=2)
    assert raised.traceback[-1].name == "explodes"
    # The module is usable afterwards (the GIL and the kernel's state unwound cleanly).
    assert quadmc.integrate(lambda x: x[:, 0], "plain_mc", 1000, s=2).evaluations == 1000


def test_a_non_finite_value_names_the_point():
    def nan_beyond_half(x):
        return np.where(x[:, 0] > 0.5, np.nan, 1.0)

    with pytest.raises(ValueError, match=r"^f returned nan at x = \(0\.[5-9]\d*, 0\.\d+\)$"):
        quadmc.integrate(nan_beyond_half, "plain_mc", 1000, s=2)


def test_a_return_of_the_wrong_length_names_f():
    with pytest.raises(ValueError, match=r"invalid f = an array of shape \(5,\) for 1000 points: "
                                         r"expected 1000 values"):
        quadmc.integrate(lambda x: x[:5, 0], "plain_mc", 1000, s=2)


@pytest.mark.parametrize("call, message", [
    (lambda: quadmc.integrate(twin, "plain_mc", 100), r"invalid s = None"),
    (lambda: quadmc.integrate(twin, "plain_mc", 100, s=4, threads=2), r"invalid threads = 2"),
    (lambda: quadmc.integrate(3, "plain_mc", 100, s=1), r"invalid f = 3"),
    (lambda: quadmc.integrate(twin, "simpson", 2, s=4), r"invalid n = 2: .*smallest grid"),
    (lambda: quadmc.integrate(twin, "no_such_method", 100, s=4), r"no_such_method"),
    (lambda: quadmc.integrate(twin, "plain_mc", 100, s=4, bogus=1), r"bogus"),
    (lambda: quadmc.integrate(twin, "plain_mc", 100, s=4, rng="mt19937"),
     r'^invalid rng = "mt19937": expected one of philox4x32_10, ars4x32_7$'),
    (lambda: quadmc.integrate(twin, "plain_mc", 100, s=4, rng=1),
     r"^invalid rng = 1: expected one of philox4x32_10, ars4x32_7$"),
    (lambda: quadmc.integrate(twin, "simpson", 100, s=2, panels=[2, 4]),
     r"invalid n = 100: expected one of the sizes `panels` gives: \[9, 25\]"),
])
def test_bad_input_is_a_value_error_naming_it(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_method_options_are_the_scene_keys(catalogue):
    # panels picks the size by its evaluations, as a scene's cell of that N.
    r = quadmc.integrate(catalogue, "simpson", 625, panels=[4])  # 4 panels: 5 nodes per axis
    assert r.evaluations == 625 and r.values == quadmc.integrate(catalogue, "simpson", 625).values
    # A dict is a nested table: importance's warp (s = 1 only).
    exp = quadmc.integrand("exp")
    warped = quadmc.integrate(exp, "importance", 1024, warp={"name": "power", "exponent": 1.0})
    assert warped.method == "importance_power" and warped.evaluations == 1024


class Counting:
    """A callable integrand that counts its calls: a refusal must come before the first."""

    def __init__(self):
        self.calls = 0

    def __call__(self, x):
        self.calls += 1
        return np.ones(len(x))


IRRADIANCE = ["irradiance_hemisphere_uniform", "irradiance_hemisphere_cosine",
              "irradiance_light_area"]


@pytest.mark.parametrize("method", IRRADIANCE)
@pytest.mark.parametrize("kind", ["callable", "genz_gaussian", "irradiance_hemisphere"])
def test_an_irradiance_method_is_refused_by_name_before_any_work(method, kind):
    # They read the light and surface of a scene's irradiance integrand (its integrand_params),
    # which integrate does not pass, so they are refused even for an irradiance Integrand.
    f = Counting()
    args = {"s": 2}
    if kind != "callable":
        f, args = quadmc.integrand(kind, s=2), {}
    with pytest.raises(ValueError) as raised:
        quadmc.integrate(f, method, 1024, **args)
    message = str(raised.value)
    assert message.startswith(f"invalid method = {method}: expected a method that integrates f "
                              f"from its values ({method} estimates irradiance"), message
    assert "quadmc.run" in message and "\n" not in message
    assert "is not a rendering integrand" not in message
    if kind == "callable":
        assert f.calls == 0


def test_a_stopping_rules_key_is_refused_without_a_tolerance():
    # quadmc.integrate runs a method at n; `stopping` and its parameters belong to a scene's
    # control = "tolerance", so they are refused by name instead of being ignored.
    f = Counting()
    with pytest.raises(ValueError) as raised:
        quadmc.integrate(f, "sobol", 1024, s=2, stopping="replicates")
    message = str(raised.value)
    assert message.startswith("invalid stopping: expected only with control = \"tolerance\""), \
        message
    assert f.calls == 0


@pytest.mark.parametrize("method", [m["name"] for m in quadmc.methods()])
def test_every_method_runs_or_is_refused_before_any_work(method):
    # With its default options on a callable in s = 2 at N = 1024: a method either runs, or raises
    # a ValueError before calling f (a missing option, a size it cannot take, s = 2 for a 1D rule,
    # an irradiance method, or one that runs only to a tolerance), never after some work.
    controls = next(m["controls"] for m in quadmc.methods() if m["name"] == method)
    f = Counting()
    try:
        r = quadmc.integrate(f, method, 1024, s=2)
    except ValueError as e:
        assert f.calls == 0, (method, str(e))
        assert "\n" not in str(e), (method, str(e))
        if not {"fixed", "budget"} & set(controls):
            assert f"{method} runs only to a tolerance" in str(e)
        return
    assert {"fixed", "budget"} & set(controls), (method, controls)
    assert method not in IRRADIANCE
    # f = 1: every method's estimate is 1 up to the rounding of its weights' sum (a Gauss or
    # Smolyak rule's weights are not dyadic); 2^-44 leaves room for thousands of them.
    assert f.calls > 0 and r.evaluations > 0 and abs(r.value - 1.0) <= 256 * EPS, (method, r)
