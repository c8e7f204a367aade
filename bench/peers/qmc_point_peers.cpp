// The point generators of the QMC throughput rows and the checks that they agree; what and why:
// qmc_point_peers.hpp.
#include "qmc_point_peers.hpp"

#include "shell_output.hpp"

#include "quadmc/core/batching.hpp"
#include "quadmc/sampling/halton_points.hpp"
#include "quadmc/sampling/rank1_lattice_points.hpp"
#include "quadmc/sampling/sobol_points.hpp"

#include <fmt/format.h>
#include <gsl/gsl_qrng.h>
#include <boost/random/sobol.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace quadmc::peers {
namespace {

// Allocates N × s doubles uninitialised (as numpy.empty, inside scipy's random(n)), lets fill
// write them, and sums the first and last point (so the writes are used); `runs` times, the
// fastest kept. The allocation is inside the timed part, its release is not (scipy_qmc.py
// drops its previous array before starting the clock, too).
template <class Fill>
generated_points timed(std::uint64_t n, std::size_t s, int runs, bool keep, Fill&& fill) {
  generated_points g;
  g.seconds = std::numeric_limits<double>::infinity();
  const std::size_t size = static_cast<std::size_t>(n) * s;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<double[]> out(new double[size]);
    fill(out.get());
    double checksum = 0.0;
    for (std::size_t j = 0; j < s; ++j) checksum += out[j] + out[size - s + j];
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    g.seconds = std::min(g.seconds, seconds);
    g.checksum = checksum;
    if (keep && r + 1 == runs) g.x.assign(out.get(), out.get() + size);
  }
  return g;
}

// quadmc's set P (any of sobol_points, halton_points, rank1_lattice_points: one constructor
// shape), built inside the timed call and generated in batches of batch_points, as the
// estimators call it (core/batching.hpp): a batch's s strided passes stay in cache, where one
// batch of all N points would sweep the whole N × s array s times.
template <class P>
point_generator quadmc_set(std::string name, std::size_t max_dimension) {
  point_generator g;
  g.name = std::move(name);
  g.family = "quadmc";
  g.max_dimension = max_dimension;
  g.generate = [](std::uint64_t n, std::size_t s, std::uint64_t seed, int runs, bool keep) {
    return timed(n, s, runs, keep, [&](double* out) {
      const P points(s, n, seed, 0);
      for (std::uint64_t first = 0; first < n; first += batch_points) {
        const std::uint64_t count = std::min<std::uint64_t>(batch_points, n - first);
        points.generate(first, std::span<double>(out + first * s, count * s));
      }
    });
  };
  return g;
}

// Boost.Random's sobol_engine (Joe–Kuo directions, the table quadmc reads): one 32-bit output per
// coordinate, scaled by 2^−32 (exact in a double). It skips the origin, so its N points are the
// sequence's points 1 … N.
point_generator boost_sobol() {
  point_generator g;
  g.name = "Boost.Random sobol_engine";
  g.family = "Boost.Random";
  g.max_dimension = sobol_matrices::max_dimension;
  g.generate = [](std::uint64_t n, std::size_t s, std::uint64_t, int runs, bool keep) {
    return timed(n, s, runs, keep, [&](double* out) {
      boost::random::sobol_engine<std::uint32_t, 32> engine(s);
      const std::size_t size = static_cast<std::size_t>(n) * s;
      for (std::size_t i = 0; i < size; ++i) out[i] = static_cast<double>(engine()) * 0x1.0p-32;
    });
  };
  return g;
}

// GSL's gsl_qrng of one type: gsl_qrng_get writes one point of s doubles per call.
point_generator gsl_qrng_generator(std::string name, const gsl_qrng_type* type) {
  point_generator g;
  g.name = std::move(name);
  g.family = "GSL";
  g.max_dimension = type->max_dimension;
  g.generate = [type, label = g.name](std::uint64_t n, std::size_t s, std::uint64_t, int runs,
                                      bool keep) {
    return timed(n, s, runs, keep, [&](double* out) {
      gsl_qrng* q = gsl_qrng_alloc(type, static_cast<unsigned>(s));
      if (q == nullptr) throw std::runtime_error(fmt::format("{}: gsl_qrng_alloc failed", label));
      int status = 0;
      for (std::uint64_t i = 0; i < n; ++i) status |= gsl_qrng_get(q, out + i * s);
      gsl_qrng_free(q);
      if (status != 0) {
        throw std::runtime_error(fmt::format("{}: gsl_qrng_get failed at N = {}", label, n));
      }
    });
  };
  return g;
}

// scipy.stats.qmc through scipy_qmc.py in a subprocess: its own best time over `runs`, and with
// keep the points (as float.hex, exact).
point_generator scipy_generator(std::string name, std::string engine, std::string python,
                                std::string script) {
  point_generator g;
  g.name = std::move(name);
  g.family = "scipy";
  g.max_dimension = 21201;  // scipy's Joe–Kuo table; Halton has no limit that matters here
  g.in_process = false;
  g.generate = [engine, python, script, label = g.name](std::uint64_t n, std::size_t s,
                                                        std::uint64_t seed, int runs, bool keep) {
    const std::string command = fmt::format("'{}' '{}' {} {} {} {} {}{} 2>&1", python, script,
                                            engine, s, n, seed, runs, keep ? " points" : "");
    const std::optional<shell_output> run = run_shell(command);
    if (!run) throw std::runtime_error(label + ": cannot start " + python);
    if (!run->failure.empty()) throw std::runtime_error(label + ": " + run->failure);
    const std::string& text = run->text;
    generated_points out;
    std::istringstream in(text);
    in >> out.seconds >> out.checksum;
    if (!in) throw std::runtime_error(label + ": unreadable output of scipy_qmc.py: " + text);
    if (keep) {
      out.x.reserve(static_cast<std::size_t>(n) * s);
      std::string word;
      while (in >> word) out.x.push_back(std::strtod(word.c_str(), nullptr));
      if (out.x.size() != static_cast<std::size_t>(n) * s) {
        throw std::runtime_error(fmt::format(
            "{}: expected {} coordinates from scipy_qmc.py, got {}", label, n * s, out.x.size()));
      }
    }
    return out;
  };
  return g;
}

const point_generator& named(const std::vector<point_generator>& generators,
                             const std::string& name) {
  const auto it = std::find_if(generators.begin(), generators.end(),
                               [&](const point_generator& g) { return g.name == name; });
  if (it == generators.end()) throw std::logic_error("no point generator named " + name);
  return *it;
}

std::vector<double> points_of(const std::vector<point_generator>& generators,
                              const std::string& name, std::uint64_t n, std::size_t s) {
  return named(generators, name).generate(n, s, 1, 1, true).x;
}

// The largest |peer point i − quadmc point i + offset| over the coordinates `first` … `last`.
double largest_difference(const std::vector<double>& peer, const std::vector<double>& ours,
                          std::size_t s, std::uint64_t offset, std::size_t first,
                          std::size_t last) {
  double worst = 0.0;
  for (std::size_t i = 0; i < peer.size() / s; ++i) {
    for (std::size_t j = first; j <= last; ++j) {
      worst = std::max(worst, std::abs(peer[i * s + j] - ours[(i + offset) * s + j]));
    }
  }
  return worst;
}

template <class Check>
point_agreement checked(std::string peer, std::string claim, Check&& check) {
  point_agreement a{std::move(peer), std::move(claim), false, {}};
  try {
    std::tie(a.holds, a.detail) = check();
  } catch (const std::exception& e) {
    a.holds = false;
    a.detail = e.what();
  }
  return a;
}

}  // namespace

// A (0, m, 2)-net in base 2: every box [a/2^k, (a+1)/2^k) × [b/2^(m−k), (b+1)/2^(m−k)) holds
// exactly one of the 2^m points ([Niederreiter 1992, Def. 4.1]). Multiplying by 2^k is exact, so
// floor gives the box without rounding.
bool is_zero_m_2_net(const std::vector<double>& x, unsigned m) {
  const std::uint64_t n = std::uint64_t{1} << m;
  if (x.size() != 2 * n) return false;
  for (unsigned k = 0; k <= m; ++k) {
    std::vector<int> count(n, 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      const auto a = static_cast<std::uint64_t>(std::ldexp(x[2 * i], static_cast<int>(k)));
      const auto b = static_cast<std::uint64_t>(std::ldexp(x[2 * i + 1], static_cast<int>(m - k)));
      if (a >= (std::uint64_t{1} << k) || b >= (std::uint64_t{1} << (m - k))) return false;
      ++count[(a << (m - k)) | b];
    }
    if (std::any_of(count.begin(), count.end(), [](int c) { return c != 1; })) return false;
  }
  return true;
}

// In every coordinate j (base b_j, the j-th prime), the first b^k ≤ N points hit each interval
// [i/b^k, (i + 1)/b^k) once: true of the Halton sequence under any digit permutation that
// depends on the digit position only (the first k digits of 0 … b^k − 1 run over every
// combination; of 1 … b^k too, b^k sharing the first k digits of 0). Points on a left edge are
// computed in floating point, hence the 1e-9 of a cell's width.
bool stratifies_each_coordinate(const std::vector<double>& x, std::uint64_t n, std::size_t s) {
  const auto bases = halton_bases();
  for (std::size_t j = 0; j < s; ++j) {
    const std::uint64_t b = bases[j];
    std::uint64_t cells = 1;
    while (cells * b <= n) cells *= b;
    std::vector<int> count(cells, 0);
    for (std::uint64_t i = 0; i < cells; ++i) {
      const auto c =
          static_cast<std::uint64_t>(std::floor(x[i * s + j] * static_cast<double>(cells) + 1e-9));
      if (c >= cells) return false;
      ++count[c];
    }
    if (std::any_of(count.begin(), count.end(), [](int c) { return c != 1; })) return false;
  }
  return true;
}

std::vector<point_generator> qmc_point_generators(const std::string& python,
                                                  const std::string& scipy_script) {
  std::vector<point_generator> g;
  constexpr std::size_t sobol_s = sobol_matrices::max_dimension;
  g.push_back(quadmc_set<sobol_points<unrandomized_digits>>("quadmc sobol none", sobol_s));
  g.push_back(quadmc_set<sobol_points<owen_scramble>>("quadmc sobol owen", sobol_s));
  g.push_back(quadmc_set<sobol_points<fast_owen_scramble>>("quadmc sobol fast_owen", sobol_s));
  g.push_back(quadmc_set<sobol_points<linear_matrix_scramble>>("quadmc sobol lms_shift", sobol_s));
  g.push_back(quadmc_set<sobol_points<digital_shift>>("quadmc sobol shift", sobol_s));
  g.push_back(quadmc_set<halton_points<unrandomized_radical_inverse>>("quadmc halton none",
                                                                      max_halton_dimension));
  g.push_back(quadmc_set<halton_points<random_digit_permutation>>("quadmc halton permutation",
                                                                  max_halton_dimension));
  g.push_back(
      quadmc_set<halton_points<nested_digit_scramble>>("quadmc halton owen", max_halton_dimension));
  g.push_back(quadmc_set<rank1_lattice_points<no_periodization>>("quadmc lattice shift",
                                                                 max_lattice_dimension));
  g.push_back(quadmc_set<rank1_lattice_points<baker_transform>>("quadmc lattice shift baker",
                                                                max_lattice_dimension));
  g.push_back(boost_sobol());
  g.push_back(gsl_qrng_generator("GSL sobol", gsl_qrng_sobol));
  g.push_back(gsl_qrng_generator("GSL niederreiter_2", gsl_qrng_niederreiter_2));
  g.push_back(gsl_qrng_generator("GSL halton", gsl_qrng_halton));
  g.push_back(gsl_qrng_generator("GSL reversehalton", gsl_qrng_reversehalton));
  g.push_back(scipy_generator("scipy Sobol scrambled", "sobol_scrambled", python, scipy_script));
  g.push_back(scipy_generator("scipy Sobol", "sobol", python, scipy_script));
  g.push_back(scipy_generator("scipy Halton scrambled", "halton_scrambled", python, scipy_script));
  g.push_back(scipy_generator("scipy Halton", "halton", python, scipy_script));
  return g;
}

std::vector<point_agreement> check_point_agreement(const std::vector<point_generator>& g) {
  constexpr unsigned m = 12;
  constexpr std::uint64_t n = std::uint64_t{1} << m;
  constexpr double halton_tolerance = 0x1.0p-52;
  std::vector<point_agreement> out;

  out.push_back(checked(
      "Boost.Random sobol_engine",
      "quadmc sobol none points 1 … 2^12 − 1 equal its first 2^12 − 1 outputs bitwise (s = 8); "
      "quadmc's point 0 is the origin",
      [&] {
        const auto ours = points_of(g, "quadmc sobol none", n, 8);
        const auto boost = points_of(g, "Boost.Random sobol_engine", n - 1, 8);
        const bool origin =
            std::all_of(ours.begin(), ours.begin() + 8, [](double v) { return v == 0.0; });
        const double d = largest_difference(boost, ours, 8, 1, 0, 7);
        return std::pair{origin && d == 0.0, fmt::format("largest difference {:g}", d)};
      }));
  out.push_back(checked(
      "GSL sobol",
      "equals quadmc sobol none points 1 … 2^12 − 1 bitwise in coordinates 1–2; differs from "
      "coordinate 3 on (Bratley–Fox direction numbers, not Joe–Kuo's; s = 8)",
      [&] {
        const auto ours = points_of(g, "quadmc sobol none", n, 8);
        const auto gsl = points_of(g, "GSL sobol", n - 1, 8);
        const double same = largest_difference(gsl, ours, 8, 1, 0, 1);
        const double rest = largest_difference(gsl, ours, 8, 1, 2, 7);
        return std::pair{
            same == 0.0 && rest > 0.0,
            fmt::format("largest difference {:g} in coordinates 1–2, {:g} in 3–8", same, rest)};
      }));
  out.push_back(
      checked("GSL niederreiter_2",
              "its first 2^12 points form a (0, 12, 2)-net in base 2 (s = 2), as quadmc "
              "sobol none and lms_shift do",
              [&] {
                const bool peer = is_zero_m_2_net(points_of(g, "GSL niederreiter_2", n, 2), m);
                const bool none = is_zero_m_2_net(points_of(g, "quadmc sobol none", n, 2), m);
                const bool lms = is_zero_m_2_net(points_of(g, "quadmc sobol lms_shift", n, 2), m);
                return std::pair{
                    peer && none && lms,
                    fmt::format("net: peer {}, quadmc none {}, lms_shift {}", peer, none, lms)};
              }));
  out.push_back(checked(
      "GSL halton",
      "its point i equals quadmc halton none point i + 1 to within 2^−52 (it skips the origin; "
      "s = 8, 2^12 − 1 points)",
      [&] {
        const auto ours = points_of(g, "quadmc halton none", n, 8);
        const auto gsl = points_of(g, "GSL halton", n - 1, 8);
        const double d = largest_difference(gsl, ours, 8, 1, 0, 7);
        return std::pair{d <= halton_tolerance, fmt::format("largest difference {:g}", d)};
      }));
  out.push_back(checked(
      "GSL reversehalton",
      "digit-permuted Halton like quadmc halton permutation: in each coordinate the first b^k "
      "≤ 2^12 points hit every interval of width b^−k once (s = 8)",
      [&] {
        const bool peer = stratifies_each_coordinate(points_of(g, "GSL reversehalton", n, 8), n, 8);
        const bool ours =
            stratifies_each_coordinate(points_of(g, "quadmc halton permutation", n, 8), n, 8);
        return std::pair{peer && ours, fmt::format("peer {}, quadmc {}", peer, ours)};
      }));
  out.push_back(checked(
      "scipy Sobol",
      "unscrambled: equals quadmc sobol none bitwise, origin included (s = 8, 2^12 points)", [&] {
        const auto ours = points_of(g, "quadmc sobol none", n, 8);
        const auto scipy = points_of(g, "scipy Sobol", n, 8);
        const double d = largest_difference(scipy, ours, 8, 0, 0, 7);
        return std::pair{d == 0.0, fmt::format("largest difference {:g}", d)};
      }));
  out.push_back(checked("scipy Sobol scrambled",
                        "LMS + digital shift like quadmc sobol lms_shift: its first 2^12 points "
                        "form a (0, 12, 2)-net in base 2 (s = 2)",
                        [&] {
                          const bool peer =
                              is_zero_m_2_net(points_of(g, "scipy Sobol scrambled", n, 2), m);
                          return std::pair{peer, fmt::format("net: {}", peer)};
                        }));
  out.push_back(
      checked("scipy Halton",
              "unscrambled: equals quadmc halton none to within 2^−52, origin included (s = 8, "
              "2^12 points)",
              [&] {
                const auto ours = points_of(g, "quadmc halton none", n, 8);
                const auto scipy = points_of(g, "scipy Halton", n, 8);
                const double d = largest_difference(scipy, ours, 8, 0, 0, 7);
                return std::pair{d <= halton_tolerance, fmt::format("largest difference {:g}", d)};
              }));
  out.push_back(checked(
      "scipy Halton scrambled",
      "digit-permuted Halton like quadmc halton permutation: in each coordinate the first b^k "
      "≤ 2^12 points hit every interval of width b^−k once (s = 8)",
      [&] {
        const bool peer =
            stratifies_each_coordinate(points_of(g, "scipy Halton scrambled", n, 8), n, 8);
        return std::pair{peer, fmt::format("peer {}", peer)};
      }));
  return out;
}

}  // namespace quadmc::peers
