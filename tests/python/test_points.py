"""quadmc.points against `quadmc points`: bitwise the same numbers for every set of the catalogue
and every combination of its options (each randomization, each periodization, each flag on and
off), at two (n, s) every set holds, n = 16 = 2^4 = 4^2 and n = 64 = 2^6 = 4^3 = 8^2, and at
n = 100, s = 5, which the grids and the nets refuse (unless allow_any_n): both refuse alike; and
under either generator, rng="philox4x32_10" (the default) or "ars4x32_7" as `--rng`."""
import itertools

import numpy as np
import pytest

import quadmc

SIZES = [(16, 2, 7, 0), (64, 3, 11, 5), (100, 5, 3, 2)]  # (n, s, seed, stream)


def combinations(point_set):
    """Every assignment of the set's options: {key: value}, a flag as True or False."""
    keys = list(point_set["options"])
    values = [[False, True] if choices is None else choices
              for choices in point_set["options"].values()]
    for chosen in itertools.product(*values):
        yield dict(zip(keys, chosen))


def cases():
    for point_set in quadmc.point_sets():
        for options in combinations(point_set):
            for n, s, seed, stream in SIZES:
                yield pytest.param(point_set["name"], options, n, s, seed, stream,
                                   id=f"{point_set['name']}-{options}-n{n}-s{s}")


def command_args(name, options, n, s, seed, stream, rng=None):
    args = ["points", name, "--n", str(n), "--s", str(s), "--seed", str(seed),
            "--stream", str(stream)]
    if rng is not None:
        args += ["--rng", rng]
    for key, value in options.items():
        flag = "--" + key.replace("_", "-")
        if value is True:
            args.append(flag)
        elif value is not False:
            args += [flag, str(value)]
    return args


def parse_csv(text, s):
    lines = text.splitlines()
    assert lines[0] == ",".join(f"x{j + 1}" for j in range(s))
    return np.array([[float(v) for v in line.split(",")] for line in lines[1:]], dtype=np.float64)


def test_every_set_has_its_options_listed():
    sets = quadmc.point_sets()
    assert len(sets) >= 8
    # The lattice lists the periodizations its points take; c0 … c3sin weight the points and are
    # the lattice method's only (docs/theory.md#lattice-periodizations).
    lattice = next(p for p in sets if p["name"] == "lattice")
    assert lattice["options"]["periodization"] == ["none", "baker"]
    # The randomized nets list their randomizations, the default first, as an option too.
    for point_set in sets:
        if point_set["randomizations"]:
            assert point_set["options"]["randomization"] == point_set["randomizations"]


@pytest.mark.parametrize("name,options,n,s,seed,stream", list(cases()))
def test_points_are_the_commands_csv_bitwise(command, name, options, n, s, seed, stream):
    result = command(*command_args(name, options, n, s, seed, stream))
    try:
        x = quadmc.points(name, n, s, seed=seed, stream=stream, **options)
    except ValueError as error:
        # A combination the set refuses is refused by both, for the same reason.
        assert result.returncode == 1, f"{name} {options}: module refused ({error}), command did not"
        assert str(error).split(": expected ")[1] in result.stderr
        return
    assert result.returncode == 0, f"{name} {options}: command refused: {result.stderr}"
    expected = parse_csv(result.stdout, s)
    assert x.shape == (n, s) and x.dtype == np.float64 and x.flags.c_contiguous
    assert expected.shape == x.shape
    differ = np.flatnonzero(expected.view(np.uint64) != x.view(np.uint64))
    assert differ.size == 0, (f"{name} {options} n={n} s={s} seed={seed}: first difference at "
                              f"{divmod(int(differ[0]), s)}: {x.flat[differ[0]]!r} != "
                              f"{expected.flat[differ[0]]!r}")


def assert_same_bits(x, expected, what):
    assert x.shape == expected.shape, what
    differ = np.flatnonzero(expected.view(np.uint64) != x.view(np.uint64))
    assert differ.size == 0, f"{what}: first difference at flat index {int(differ[0])}"


# Every set with its default options under ARS-4x32-7 (docs/theory.md#counter-based-generators):
# the module and `quadmc points --rng` hand the generator to the same entry, so the bits agree
# for the other generator too, not only for Philox, which every case above draws from.
@pytest.mark.parametrize("name", [p["name"] for p in quadmc.point_sets()])
def test_ars_points_are_the_commands_rng_csv_bitwise(command, name):
    n, s, seed, stream = SIZES[1]
    result = command(*command_args(name, {}, n, s, seed, stream, rng="ars4x32_7"))
    assert result.returncode == 0, f"{name}: command refused: {result.stderr}"
    x = quadmc.points(name, n, s, seed=seed, stream=stream, rng="ars4x32_7")
    assert_same_bits(x, parse_csv(result.stdout, s), f"{name} --rng ars4x32_7")


@pytest.mark.parametrize("name", [p["name"] for p in quadmc.point_sets()])
def test_the_default_generator_is_philox(name):
    n, s, seed, stream = SIZES[1]
    assert_same_bits(quadmc.points(name, n, s, seed=seed, stream=stream),
                     quadmc.points(name, n, s, seed=seed, stream=stream, rng="philox4x32_10"),
                     f"{name}: default against rng=\"philox4x32_10\"")


@pytest.mark.parametrize("name, options", [("independent", {}), ("jittered", {}),
                                           ("latin_hypercube", {}),
                                           ("sobol", {"randomization": "owen"}),
                                           ("lattice", {})])
def test_ars_draws_other_points_than_philox(name, options):
    philox = quadmc.points(name, 64, 3, seed=11, **options)
    ars = quadmc.points(name, 64, 3, seed=11, rng="ars4x32_7", **options)
    assert np.all((ars >= 0) & (ars < 1))
    # Two generators agreeing on a 53-bit uniform has probability 2^-53 per coordinate: any
    # equal row would mean the keyword did not reach the set.
    assert not np.any(np.all(philox == ars, axis=1)), name


def test_an_unrandomized_set_is_the_same_under_both_generators():
    # It draws no random numbers.
    assert_same_bits(quadmc.points("sobol", 64, 3, seed=11, randomization="none"),
                     quadmc.points("sobol", 64, 3, seed=11, randomization="none",
                                   rng="ars4x32_7"), "sobol none")


def test_points_lie_in_the_unit_cube_and_depend_on_the_seed():
    a = quadmc.points("sobol", 256, 4, seed=1, randomization="owen")
    b = quadmc.points("sobol", 256, 4, seed=2, randomization="owen")
    assert np.all((a >= 0) & (a < 1))
    assert not np.array_equal(a, b)
    # The unrandomized sequence does not depend on the seed.
    assert np.array_equal(quadmc.points("sobol", 8, 2, seed=1, randomization="none"),
                          quadmc.points("sobol", 8, 2, seed=2, randomization="none"))


def error_text(command, args):
    """The command's one-line error without its 'quadmc: ' prefix."""
    result = command(*args)
    assert result.returncode == 1, result.stderr
    return result.stderr.strip().removeprefix("quadmc: ")


@pytest.mark.parametrize("module_call,args,flag,keyword", [
    (lambda: quadmc.points("sobol", 100, 2), ["--n", "100", "--s", "2"], "--n", "n"),
    (lambda: quadmc.points("sobol", 16, 2, randomization="nope"),
     ["--n", "16", "--s", "2", "--randomization", "nope"], "--randomization", "randomization"),
    (lambda: quadmc.points("halton", 16, 2, periodization="baker"),
     ["--n", "16", "--s", "2", "--periodization", "baker"], "--periodization", "periodization"),
    (lambda: quadmc.points("sobol", 16, 3668), ["--n", "16", "--s", "3668"], "--s", "s"),
    (lambda: quadmc.points("sobol", 16, 1834, interlacing=2),
     ["--n", "16", "--s", "1834", "--interlacing", "2"], "--s", "s"),
    # The lattice's weighted periodizations weight the points: no equal-weight points to give.
    (lambda: quadmc.points("lattice", 16, 2, periodization="c1sin"),
     ["--n", "16", "--s", "2", "--periodization", "c1sin"], "--periodization", "periodization"),
    (lambda: quadmc.points("sobol", 16, 2, rng="mt19937"),
     ["--n", "16", "--s", "2", "--rng", "mt19937"], "--rng", "rng"),
])
def test_refusals_are_the_commands_text(command, module_call, args, flag, keyword):
    set_name = "sobol"
    if "--periodization" in args:
        set_name = "lattice" if "c1sin" in args else "halton"
    expected = error_text(command, ["points", set_name, "--seed", "0", *args])
    with pytest.raises(ValueError) as error:
        module_call()
    assert str(error.value) == expected.replace(flag, keyword, 1)


@pytest.mark.parametrize("call,parameter", [
    (lambda: quadmc.points("nope", 16, 2), "invalid set = nope: expected one of: "),
    (lambda: quadmc.points("sobol", 0, 2), "invalid n = 0: "),
    (lambda: quadmc.points("sobol", 16, -1), "invalid s = -1: "),
    (lambda: quadmc.points("sobol", 16, 2, seed=-3), "invalid seed = -3: "),
    (lambda: quadmc.points("sobol", 16, 2, allow_any_n="yes"), "invalid allow_any_n = yes: expected True or False"),
    (lambda: quadmc.points("sobol", 16, 2, interlacing="2"),
     "invalid interlacing = 2: expected an integer, one of 1, 2, 3"),
    (lambda: quadmc.points("sobol", 16, 2, interlacing=4), "invalid interlacing = 4: expected one of 1, 2, 3"),
    (lambda: quadmc.points("sobol", 16, 2, rng="philox"),
     'invalid rng = "philox": expected one of philox4x32_10, ars4x32_7'),
    (lambda: quadmc.points("sobol", 16, 2, rng=None),
     "invalid rng = None: expected one of philox4x32_10, ars4x32_7"),
])
def test_bad_arguments_are_value_errors_naming_the_parameter(call, parameter):
    with pytest.raises(ValueError) as error:
        call()
    assert str(error.value).startswith(parameter)
    assert "\n" not in str(error.value)

