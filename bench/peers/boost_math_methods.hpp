// Boost.Math's integrators as peers (Boost 1.74, Debian's libboost-dev):
//  - naive_monte_carlo (boost/math/quadrature/naive_monte_carlo.hpp), with 1 worker thread and
//    with its default, std::thread::hardware_concurrency();
//  - trapezoidal, gauss_kronrod<double, 15> and tanh_sinh for s = 1 (Boost.Math docs,
//    "Quadrature and Differentiation").
//
// How they are called, so that the comparison is honest:
//  - naive_monte_carlo is driven by an error goal, not a number of calls. It gets the goal
//    √(V̂/N), V̂ the integrand's variance estimated beforehand by quadmc (2^16 points), so it stops
//    near N calls; but its master thread checks the goal only every 100 ms
//    (std::this_thread::sleep_for(100ms) in m_integrate), so a run never lasts less than ~0.1 s
//    and usually makes more than N calls. Its reported calls() are used for every rate, so the
//    rate is fair; the overshoot is the API's. bounds are finite and singular = false (the
//    integrands are bounded, so no end point needs to be avoided); the generator is its default
//    std::mt19937_64, seeded with a fixed non-zero seed. Its threads race to the goal, so a
//    fixed seed does not fix the result (measured and reported in the README).
//  - The 1D rules are tolerance driven: the ladder asks for tolerances 10^−k, the evaluations
//    are counted by the functor. tanh_sinh's abscissa tables are built once per method, as a
//    user would keep the integrator; trapezoidal gets max_refinements = 20 (default 12) so that
//    it can reach tight tolerances on non-periodic integrands at O(h²).
#pragma once

#include "peer_method.hpp"

#include "point_adapter.hpp"  // bench/common

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/naive_monte_carlo.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/quadrature/trapezoidal.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace quadmc::peers {

// naive_monte_carlo with `threads` worker threads (0: its default, hardware_concurrency()).
template <class F>
peer_method boost_naive_monte_carlo(const F& f, unsigned threads, double variance,
                                    const std::vector<std::uint64_t>& ladder,
                                    std::uint64_t throughput_n) {
  const unsigned workers = threads == 0 ? std::thread::hardware_concurrency() : threads;
  peer_method m;
  m.name = threads == 0 ? "Boost naive_monte_carlo (default threads)" : "Boost naive_monte_carlo";
  m.family = "Boost.Math";
  m.threads = workers;
  m.random = true;
  m.kind = control_kind::target_calls;
  m.ladder = ladder;
  m.throughput_control = throughput_n;
  m.run = [&f, workers, variance](std::uint64_t n, std::uint64_t seed) {
    const std::size_t s = f.dimension();
    auto g = [&f, s](const std::vector<double>& x) {
      return bench::evaluate_point(f, x.data(), s);
    };
    const std::vector<std::pair<double, double>> bounds(s, {0.0, 1.0});
    const double goal = std::sqrt(variance / static_cast<double>(n));
    boost::math::quadrature::naive_monte_carlo<double, decltype(g)> mc(
        g, bounds, goal, /*singular=*/false, workers, seed == 0 ? 1 : seed);
    auto future = mc.integrate();
    const double value = future.get();
    return run_result{value, mc.calls()};
  };
  return m;
}

enum class boost_quadrature_1d { trapezoidal, gauss_kronrod_15, tanh_sinh };

// A 1D rule from Boost.Math; ladder = tolerance exponents k (tolerance 10^−k).
template <class F>
peer_method boost_quadrature(boost_quadrature_1d rule, const F& f,
                             const std::vector<std::uint64_t>& tolerance_exponents) {
  static constexpr const char* names[] = {"Boost trapezoidal", "Boost gauss_kronrod<15>",
                                          "Boost tanh_sinh"};
  peer_method m;
  m.name = names[static_cast<int>(rule)];
  m.family = "Boost.Math";
  m.threads = 1;
  m.random = false;
  m.kind = control_kind::tolerance;
  m.ladder = tolerance_exponents;
  m.throughput_control = 0;
  auto integrator = std::make_shared<boost::math::quadrature::tanh_sinh<double>>();
  m.run = [&f, rule, integrator](std::uint64_t k, std::uint64_t) {
    std::uint64_t calls = 0;
    auto g = [&f, &calls](double x) {
      ++calls;
      return bench::evaluate_point(f, &x, 1);
    };
    const double tolerance = std::pow(10.0, -static_cast<double>(k));
    double value = 0.0;
    switch (rule) {
      case boost_quadrature_1d::trapezoidal:
        value = boost::math::quadrature::trapezoidal(g, 0.0, 1.0, tolerance, 20);
        break;
      case boost_quadrature_1d::gauss_kronrod_15:
        value = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(g, 0.0, 1.0, 15,
                                                                              tolerance);
        break;
      case boost_quadrature_1d::tanh_sinh:
        value = integrator->integrate(g, 0.0, 1.0, tolerance);
        break;
    }
    return run_result{value, calls};
  };
  return m;
}

}  // namespace quadmc::peers
