// The Monte Carlo methods by name, over a type-erased integrand: the entry points of the scene
// runner, which picks a method from a scene file at run time. Each call picks the point set
// once; below that the kernels are templates (one virtual call per 256-point batch, inside
// any_integrand). Compiled once in lib/src/estimators/sampling_method.cpp.
//
// Every run is named by (seed, stream, N, threads) and is bitwise reproducible for any thread
// count. Point sets that need N = k^s (jittered, unjittered) reject other N with the nearest
// valid sizes: call accepts_size() first to skip a cell with a reason.
#pragma once

#include "quadmc/estimators/estimate.hpp"
#include "quadmc/functions/any_integrand.hpp"
#include "quadmc/functions/irradiance.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace quadmc {

enum class point_set_kind {
  independent,      // plain Monte Carlo ("plain")
  jittered,         // one point per stratum, N = k^s
  unjittered,       // stratum centres, randomly shifted as a whole (N = k^s)
  padded_jittered,  // 2D jittered groups, shuffled across groups (any N)
  latin_hypercube,  // any N
};

std::string_view to_string(point_set_kind kind) noexcept;
// Accepts the names above and "plain" for independent; throws invalid_argument listing them.
point_set_kind parse_point_set_kind(std::string_view name);
// Whether the point set can hold exactly n points in s dimensions.
bool accepts_size(point_set_kind kind, std::size_t s, std::uint64_t n);

// Plain Monte Carlo average of f over its box with the named point set.
estimate run_monte_carlo(point_set_kind kind, const any_integrand& f, std::uint64_t seed,
                         std::uint64_t stream, std::uint64_t n, unsigned threads);

// Importance sampling of a 1D integrand on its interval [a, b]: X = a + (b − a)·W(U) with W a
// warp on [0,1] (power: p = (k+1)x^k; truncated exponential: p = λe^(λx)/(e^λ − 1)) and the
// density p(W)/(b − a). The warp's u come from the named point set.
enum class unit_warp_kind { power, truncated_exponential };
estimate run_importance(point_set_kind kind, const any_integrand& f, unit_warp_kind warp,
                        double parameter, std::uint64_t seed, std::uint64_t stream, std::uint64_t n,
                        unsigned threads);

enum class irradiance_sampling { uniform_hemisphere, cosine_hemisphere, light_area };
estimate run_irradiance(irradiance_sampling technique, point_set_kind kind,
                        const irradiance_setup& setup, std::uint64_t seed, std::uint64_t stream,
                        std::uint64_t n, unsigned threads);

}  // namespace quadmc
