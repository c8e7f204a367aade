// Quasi-Monte Carlo point generation as a throughput study: quadmc's Sobol' (every
// randomization), Halton and lattice points beside Boost.Random's sobol_engine, GSL's gsl_qrng
// (sobol, niederreiter_2, halton, reversehalton) and scipy.stats.qmc (Sobol and Halton, timed in
// a /usr/bin/python3 subprocess), and the checks that each peer makes points of the same kind as
// the quadmc set it is compared with.
//
// Use it from the peers driver (measurement.cpp) and its test (tests/peers/). Equal work: every
// generator writes the same N × s doubles, row-major, into an array it allocates uninitialised
// inside the timed call (numpy's `random(n)` allocates its result the same way), set-up included
// (scrambles, GSL state, scipy's engine). Points only, no integrand: not a statement about
// integration error (that is `quadmc run`). Not for s above a peer's own limit (GSL sobol 40,
// niederreiter_2 12, halton 1229): such points are skipped, with the peer's limit named.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace quadmc::peers {

struct generated_points {
  std::vector<double> x;  // N × s, row-major (only filled when asked for: see generate)
  double checksum = 0.0;  // a sum over the first and last point, so no write can be optimised away
  double seconds = 0.0;   // the generator's own time (scipy: measured inside the subprocess)
};

struct point_generator {
  std::string name;    // e.g. "quadmc sobol owen", "GSL sobol", "scipy Sobol scrambled"
  std::string family;  // "quadmc", "Boost.Random", "GSL", "scipy"
  std::size_t max_dimension = 0;
  // Generates N points in s dimensions (randomized ones with `seed`) `runs` times and returns
  // the fastest run's time; with keep, the points themselves too. In-process generators are
  // called with runs = 1 in rounds (measurement.cpp); scipy once with every run, since each
  // subprocess spends about 0.5 s of CPU importing scipy. Throws std::runtime_error when the peer
  // fails (scipy missing, a GSL allocation failing).
  std::function<generated_points(std::uint64_t n, std::size_t s, std::uint64_t seed, int runs,
                                 bool keep)>
      generate;
  bool in_process = true;  // false: scipy (a subprocess per call)
};

// quadmc's sets first (sobol none/owen/fast_owen/lms_shift/shift, halton none/permutation/owen,
// lattice shift with and without the baker's transform), then the peers. `scipy_script` is
// bench/peers/scipy_qmc.py; `python` the interpreter that runs it (/usr/bin/python3).
std::vector<point_generator> qmc_point_generators(const std::string& python,
                                                  const std::string& scipy_script);

// The kinds the claims check, on N × s points, row-major:
// a (0, m, 2)-net in base 2: every box [a/2^k, (a+1)/2^k) × [b/2^(m−k), (b+1)/2^(m−k)) holds
// exactly one of the 2^m points ([Niederreiter 1992, Def. 4.1]);
bool is_zero_m_2_net(const std::vector<double>& x, unsigned m);
// digit-permuted Halton: in every coordinate j (base b_j, the j-th prime) the first b^k ≤ N
// points hit each interval [i/b^k, (i + 1)/b^k) exactly once.
bool stratifies_each_coordinate(const std::vector<double>& x, std::uint64_t n, std::size_t s);

// One claim that a peer's points are of the same kind as quadmc's, with whether it held.
struct point_agreement {
  std::string peer;
  std::string claim;
  bool holds = false;
  std::string detail;  // what was measured (e.g. the largest difference), or why it failed
};

// The claims, each checked on the generators' own output (the same calls that are timed):
//  - Boost sobol_engine: points 1 … 2^12 − 1 of quadmc's unrandomized Sobol' (s = 8) equal its
//    first 2^12 − 1 outputs bitwise (it skips the origin), and quadmc's point 0 is the origin;
//  - GSL sobol: equal bitwise to quadmc's points 1 … 2^12 − 1 in coordinates 1 and 2 only (its
//    Bratley–Fox direction numbers differ from Joe–Kuo's from coordinate 3 on, which is checked
//    too);
//  - GSL niederreiter_2 and scipy's scrambled Sobol: their first 2^12 points in s = 2 form a
//    (0, 12, 2)-net in base 2, as quadmc's Sobol' points (unrandomized and LMS-scrambled) do;
//  - GSL halton: point i equals quadmc's unrandomized Halton point i + 1 to within 2^−52
//    (it skips the origin and accumulates digits in floating point; quadmc rounds r/b^K once or
//    twice, halton_points.hpp);
//  - GSL reversehalton and scipy's scrambled Halton: digit-permuted Halton points like quadmc's
//    `permutation`: in every coordinate (base b) the first b^k points ≤ 4096 hit each interval
//    [i/b^k, (i + 1)/b^k) once;
//  - scipy Sobol and Halton unscrambled: equal to quadmc's unrandomized points (Sobol' bitwise;
//    Halton to within 2^−52), origin included.
// A failing peer (scipy not installed) gives a claim that does not hold, with its message.
std::vector<point_agreement> check_point_agreement(const std::vector<point_generator>& generators);

}  // namespace quadmc::peers
