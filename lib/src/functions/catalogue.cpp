// The integrand catalogue (catalogue.hpp): names, keys, and construction from integrand_params.
#include "quadmc/functions/catalogue.hpp"

#include "quadmc/functions/classic_1d.hpp"
#include "quadmc/functions/genz.hpp"
#include "quadmc/functions/geometric_asian.hpp"
#include "quadmc/functions/indicators.hpp"
#include "quadmc/functions/irradiance.hpp"
#include "quadmc/functions/ishigami.hpp"
#include "quadmc/functions/keister.hpp"
#include "quadmc/functions/random_regions.hpp"
#include "quadmc/functions/sobol_g.hpp"
#include "quadmc/functions/stability_1d.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace quadmc {
namespace {

constexpr std::array<std::string_view, 0> no_keys{};
constexpr std::array<std::string_view, 2> genz_vector_keys{"a", "u"};
constexpr std::array<std::string_view, 3> genz_discontinuous_keys{"a", "u", "cut"};
constexpr std::array<std::string_view, 2> interval_keys{"lower", "upper"};
constexpr std::array<std::string_view, 1> c_key{"c"};
constexpr std::array<std::string_view, 1> center_key{"center"};
constexpr std::array<std::string_view, 1> r_key{"r"};
constexpr std::array<std::string_view, 1> w_key{"w"};
constexpr std::array<std::string_view, 1> t_key{"t"};
constexpr std::array<std::string_view, 1> a_key{"a"};
constexpr std::array<std::string_view, 2> irradiance_keys{"occluder", "radiance"};
constexpr std::array<std::string_view, 2> ab_keys{"a", "b"};
constexpr std::array<std::string_view, 2> heaviside_keys{"normal", "point"};
constexpr std::array<std::string_view, 2> gaussian_bump_keys{"mean", "scales"};
constexpr std::array<std::string_view, 1> angle_key{"angle"};
constexpr std::array<string_key, 1> genz_string_keys{{{"coefficient_decay", genz_decay_names}}};
constexpr std::array<std::string_view, 5> option_keys{"spot", "strike", "rate", "volatility",
                                                      "maturity"};
constexpr std::array<string_key, 1> asian_string_keys{{{"construction", path_construction_names}}};

constexpr std::string_view genz_doc =
    "a: difficulty, length s (default: drawn from seed, w = 1 − U, a = b·w/Σw with Genz's b), "
    "not subnormal, and such that f's values and ∫f are normal doubles; u: shift in [0,1], "
    "length s (default: drawn from seed); coefficient_decay: \"none\" (default), "
    "\"quadratic\" or \"exponential\", drawn w multiplied by j⁻² or 2⁻ʲ before normalising "
    "(fewer effective dimensions at the same Σa = b), not with an explicit a";

std::size_t dimension_or(const integrand_params& p, std::size_t default_s) {
  return p.dimension == 0 ? default_s : p.dimension;
}

void require_fixed_dimension(const integrand_params& p, std::size_t s, std::string_view name) {
  require(p.dimension == 0 || p.dimension == s, "dimension", p.dimension,
          fmt::format("{} (or 0 for the default) for {}", s, name));
}

double scalar_or(const integrand_params& p, std::string_view key, double fallback) {
  const auto it = p.scalars.find(key);
  return it == p.scalars.end() ? fallback : it->second;
}

std::vector<double> vector_of_length(const integrand_params& p, std::string_view key, std::size_t s,
                                     std::vector<double> fallback) {
  const auto it = p.vectors.find(key);
  if (it == p.vectors.end()) return fallback;
  require(it->second.size() == s, key, fmt::format("[{}]", fmt::join(it->second, ", ")),
          fmt::format("a vector of length dimension = {}", s));
  return it->second;
}

// The Genz key coefficient_decay (default none). It shapes only the a drawn from the seed, so it
// is refused beside an explicit a rather than silently ignored.
genz_decay decay_of(const integrand_params& p) {
  const auto it = p.strings.find("coefficient_decay");
  if (it == p.strings.end()) return genz_decay::none;
  const genz_decay decay = genz_decay_from(it->second);
  require(!p.vectors.contains("a"), "coefficient_decay", fmt::format("\"{}\"", it->second),
          "no explicit a beside it (coefficient_decay shapes only the a drawn from the seed; "
          "give a or coefficient_decay, not both)");
  return decay;
}

template <class Family, genz_family F>
any_integrand make_genz(const integrand_params& p) {
  const std::size_t s = dimension_or(p, 1);
  require(s >= 1, "dimension", s, "s ≥ 1");
  genz_parameters drawn = genz_random_parameters(F, s, p.seed, decay_of(p));
  std::vector<double> a = vector_of_length(p, "a", s, std::move(drawn.a));
  std::vector<double> u = vector_of_length(p, "u", s, std::move(drawn.u));
  if constexpr (std::is_same_v<Family, genz_discontinuous>) {
    std::vector<std::size_t> cut;
    if (const auto it = p.vectors.find("cut"); it != p.vectors.end()) {
      for (double c : it->second) {
        require(std::isfinite(c) && c >= 1.0 && c == std::floor(c), "cut", c,
                "1-based integer indices");
        cut.push_back(static_cast<std::size_t>(c));
      }
      require(!cut.empty(), "cut", "[]", "at least one index (omit the key for the default)");
    }
    return any_integrand(Family(std::move(a), std::move(u), std::move(cut)));
  } else {
    return any_integrand(Family(std::move(a), std::move(u)));
  }
}

// The parameters a Genz family draws from the seed when the scene omits them (genz.hpp).
template <genz_family F>
drawn_parameters draw_genz(const integrand_params& p) {
  genz_parameters drawn = genz_random_parameters(F, p.dimension, p.seed, decay_of(p));
  return {{"a", std::move(drawn.a)}, {"u", std::move(drawn.u)}};
}

// 1D families on an interval [lower, upper], by default [0, 1] ([0, π] for sin).
template <class Family>
any_integrand make_interval(const integrand_params& p) {
  return any_integrand(Family(scalar_or(p, "lower", 0.0), scalar_or(p, "upper", 1.0)));
}

any_integrand make_sin(const integrand_params& p) {
  return any_integrand(sin_1d(scalar_or(p, "lower", 0.0), scalar_or(p, "upper", std::numbers::pi)));
}

// 1D families without parameters.
template <class Family>
any_integrand make_fixed(const integrand_params& /*params*/) {
  return any_integrand(Family{});
}

// 1D families with a kink or jump at c (default 0.3).
template <class Family>
any_integrand make_located(const integrand_params& p) {
  return any_integrand(Family(scalar_or(p, "c", 0.3)));
}

any_integrand make_disk(const integrand_params& p) {
  const std::size_t s = dimension_or(p, 1);
  return any_integrand(disk_indicator(vector_of_length(p, "center", s, std::vector<double>(s, 0.5)),
                                      scalar_or(p, "r", 0.45)));
}

any_integrand make_half_space(const integrand_params& p) {
  const std::size_t s = dimension_or(p, 1);
  std::vector<double> w = vector_of_length(p, "w", s, std::vector<double>(s, 1.0));
  // 0.6·Σw; when Σw overflows (weights near 1e308), as Σ 0.6·wᵢ, which may still be finite.
  double t = 0.6 * std::accumulate(w.begin(), w.end(), 0.0);
  if (!std::isfinite(t)) {
    t = 0.0;
    for (double wi : w) t += 0.6 * wi;
  }
  return any_integrand(half_space_indicator(std::move(w), scalar_or(p, "t", t)));
}

// The random-region families (random_regions.hpp): omitted parameters drawn from the seed.
any_integrand make_heaviside_random(const integrand_params& p) {
  const std::size_t s = dimension_or(p, 1);
  heaviside_parameters drawn = heaviside_random_parameters(s, p.seed);
  return any_integrand(heaviside_random(vector_of_length(p, "normal", s, std::move(drawn.normal)),
                                        vector_of_length(p, "point", s, std::move(drawn.point))));
}
drawn_parameters draw_heaviside_random(const integrand_params& p) {
  heaviside_parameters drawn = heaviside_random_parameters(p.dimension, p.seed);
  return {{"normal", std::move(drawn.normal)}, {"point", std::move(drawn.point)}};
}

any_integrand make_disk_random(const integrand_params& p) {
  require_fixed_dimension(p, 2, "disk_random");
  disk_parameters drawn = disk_random_parameters(p.seed);
  return any_integrand(disk_random(vector_of_length(p, "center", 2, std::move(drawn.center)),
                                   scalar_or(p, "r", drawn.r)));
}
drawn_parameters draw_disk_random(const integrand_params& p) {
  disk_parameters drawn = disk_random_parameters(p.seed);
  return {{"center", std::move(drawn.center)}, {"r", {drawn.r}}};
}

any_integrand make_gaussian_random(const integrand_params& p) {
  require_fixed_dimension(p, 2, "gaussian_random");
  gaussian_2d_parameters drawn = gaussian_random_parameters(p.seed);
  return any_integrand(gaussian_random(vector_of_length(p, "mean", 2, std::move(drawn.mean)),
                                       vector_of_length(p, "scales", 2, std::move(drawn.scales)),
                                       scalar_or(p, "angle", drawn.angle)));
}
drawn_parameters draw_gaussian_random(const integrand_params& p) {
  gaussian_2d_parameters drawn = gaussian_random_parameters(p.seed);
  return {{"mean", std::move(drawn.mean)},
          {"scales", std::move(drawn.scales)},
          {"angle", {drawn.angle}}};
}

any_integrand make_sobol_g(const integrand_params& p) {
  const std::size_t s = dimension_or(p, 1);
  require(s >= 1, "dimension", s, "s ≥ 1");
  return any_integrand(sobol_g(vector_of_length(p, "a", s, sobol_g::default_a(s))));
}

any_integrand make_ishigami(const integrand_params& p) {
  return any_integrand(ishigami(scalar_or(p, "a", 7.0), scalar_or(p, "b", 0.1)));
}

any_integrand make_keister(const integrand_params& p) {
  return any_integrand(keister(dimension_or(p, 1)));
}

any_integrand make_geometric_asian(const integrand_params& p) {
  geometric_asian_parameters g;
  g.spot = scalar_or(p, "spot", g.spot);
  g.strike = scalar_or(p, "strike", g.strike);
  g.rate = scalar_or(p, "rate", g.rate);
  g.volatility = scalar_or(p, "volatility", g.volatility);
  g.maturity = scalar_or(p, "maturity", g.maturity);
  if (const auto it = p.strings.find("construction"); it != p.strings.end()) {
    g.construction = parse_path_construction(it->second);
  }
  return any_integrand(geometric_asian(dimension_or(p, 1), g));
}

template <class Family>
any_integrand make_irradiance(const integrand_params& p) {
  return any_integrand(Family(make_irradiance_setup(p)));
}

const std::array<catalogue_entry, 31> entries = {{
    {"genz_oscillatory", "cos(2πu₁ + Σ aᵢxᵢ) on [0,1]^s", "analytic", genz_vector_keys, no_keys,
     genz_doc, make_genz<genz_oscillatory, genz_family::oscillatory>,
     draw_genz<genz_family::oscillatory>, false, false, 0, genz_string_keys},
    {"genz_product_peak", "Π 1/(aᵢ⁻² + (xᵢ − uᵢ)²) on [0,1]^s", "analytic", genz_vector_keys,
     no_keys, genz_doc, make_genz<genz_product_peak, genz_family::product_peak>,
     draw_genz<genz_family::product_peak>, false, false, 0, genz_string_keys},
    {"genz_corner_peak", "(1 + Σ aᵢxᵢ)^−(s+1) on [0,1]^s", "analytic", genz_vector_keys, no_keys,
     "a, u, coefficient_decay as the other Genz families; s ≤ 20 (its closed form sums 2^s terms "
     "in 50-digit arithmetic "
     "and must carry a rounding bound ≤ 1e-10, true for Genz's difficulty at every s ≤ 20)",
     make_genz<genz_corner_peak, genz_family::corner_peak>, draw_genz<genz_family::corner_peak>,
     false, true, 0, genz_string_keys},
    {"genz_gaussian", "exp(−Σ aᵢ²(xᵢ − uᵢ)²) on [0,1]^s", "analytic", genz_vector_keys, no_keys,
     genz_doc, make_genz<genz_gaussian, genz_family::gaussian>, draw_genz<genz_family::gaussian>,
     false, false, 0, genz_string_keys},
    {"genz_continuous", "exp(−Σ aᵢ|xᵢ − uᵢ|) on [0,1]^s", "C0", genz_vector_keys, no_keys, genz_doc,
     make_genz<genz_continuous, genz_family::continuous>, draw_genz<genz_family::continuous>, false,
     false, 0, genz_string_keys},
    {"genz_discontinuous", "0 if x_c > u_c for a c in cut, else exp(Σ aᵢxᵢ) on [0,1]^s",
     "discontinuous", genz_discontinuous_keys, no_keys,
     "a, u, coefficient_decay as the other Genz families; cut: 1-based indices of the cut "
     "coordinates, distinct, in "
     "1..s (default [1, 2], [1] when s = 1; [1, …, s] cuts every coordinate)",
     make_genz<genz_discontinuous, genz_family::discontinuous>,
     draw_genz<genz_family::discontinuous>, false, false, 0, genz_string_keys},
    {"poly", "x⁵ on [lower, upper]", "analytic", no_keys, interval_keys,
     "lower, upper: the interval (default 0, 1), |lower|, |upper| ≤ 1e51; dimension 1",
     make_interval<poly_1d>, nullptr, false, false, 1},
    {"exp", "eˣ on [lower, upper]", "analytic", no_keys, interval_keys,
     "lower, upper: the interval (default 0, 1), upper ≤ 709.78; dimension 1",
     make_interval<exp_1d>, nullptr, false, false, 1},
    {"sin", "sin x on [lower, upper]", "analytic", no_keys, interval_keys,
     "lower, upper: the interval (default 0, π), of finite width; dimension 1", make_sin, nullptr,
     false, false, 1},
    {"inverse_quadratic", "1/(1 + x²) on [0, 1]", "analytic", no_keys, no_keys,
     "no parameters; dimension 1", make_fixed<inverse_quadratic_1d>, nullptr, false, false, 1},
    {"sqrt", "√x on [0, 1]", "singular", no_keys, no_keys, "no parameters; dimension 1",
     make_fixed<sqrt_1d>, nullptr, false, false, 1},
    {"abs_kink", "|x − c| on [0, 1]", "C0", no_keys, c_key,
     "c: the kink, in [0, 1] (default 0.3); dimension 1", make_located<abs_kink_1d>, nullptr, false,
     false, 1},
    {"step", "1 if x ≥ c else 0 on [0, 1]", "discontinuous", no_keys, c_key,
     "c: the jump, in [0, 1] (default 0.3); dimension 1", make_located<step_1d>, nullptr, false,
     false, 1},
    {"disk_indicator", "1 if ‖x − center‖ ≤ r else 0 on [0,1]^s (disk for s = 2, ball otherwise)",
     "discontinuous", center_key, r_key,
     "center: length s (default all 0.5); r: radius > 0 (default 0.45); the ball must lie "
     "inside the cube",
     make_disk, nullptr, false, false, 0},
    {"half_space", "1 if Σ wᵢxᵢ ≤ t else 0 on [0,1]^s", "discontinuous", w_key, t_key,
     "w: non-zero weights of any sign and magnitude, within 2^1021 of each other, length s "
     "(default all 1); t: in (Σ of the negative wᵢ, Σ of the positive wᵢ) (default 0.6·Σw); "
     "s ≤ 20",
     make_half_space, nullptr, false, true, 0},
    {"heaviside_random", "1 if n·(x − p) ≤ 0 else 0 on [0,1]^s, a random edge", "discontinuous",
     heaviside_keys, no_keys,
     "normal: non-zero, length s (default: a uniform unit vector drawn from seed); point: in "
     "[0,1]^s, on the plane (default: uniform, drawn from seed); s ≤ 20",
     make_heaviside_random, draw_heaviside_random, false, true, 0},
    {"disk_random", "1 if ‖x − center‖ ≤ r else 0 on [0,1]², the disk clipped to the square",
     "discontinuous", center_key, r_key,
     "center: in [0,1]² (default uniform, drawn from seed); r: 0 < r ≤ 1 (default uniform in "
     "[0.1, 0.4], drawn from seed); dimension 2",
     make_disk_random, draw_disk_random, false, false, 2},
    {"gaussian_random",
     "exp(−½ (x − mean)ᵀ R diag(scales⁻²) Rᵀ (x − mean)) on [0,1]², R the "
     "rotation by angle",
     "analytic", gaussian_bump_keys, angle_key,
     "mean: in [0,1]² (default uniform); scales: σ₁, σ₂ in [0.01, 10] (default log-uniform in "
     "[0.05, 0.5]); angle: radians (default uniform in [0, π)); all drawn from seed when "
     "omitted; dimension 2",
     make_gaussian_random, draw_gaussian_random, false, false, 2},
    {"sobol_g", "Π (|4xᵢ − 2| + aᵢ)/(1 + aᵢ) on [0,1]^s", "C0", a_key, no_keys,
     "a: aᵢ ≥ 0, length s (default aᵢ = (i − 1)/2)", make_sobol_g, nullptr, false, false, 0},
    {"keister", "π^{s/2}·cos(‖Φ⁻¹(x)‖/√2) on [0,1]^s", "singular", no_keys, no_keys,
     "no parameters; 1 ≤ s ≤ 20", make_keister, nullptr, false, false, 0},
    {"ishigami", "sin X₁ + a·sin² X₂ + b·X₃⁴·sin X₁, Xᵢ = π(2xᵢ − 1), on [0,1]³", "analytic",
     no_keys, ab_keys, "a, b: finite numbers (default 7, 0.1); dimension 3", make_ishigami, nullptr,
     false, false, 3},
    {"geometric_asian",
     "e^(−rT)·max((Π S(tᵢ))^(1/s) − K, 0), Black–Scholes path at tᵢ = iT/s from Φ⁻¹(x), on [0,1]^s",
     "C0", no_keys, option_keys,
     "spot S₀ > 0, strike K > 0, rate r, volatility σ > 0, maturity T > 0 (default 100, 100, "
     "0.05, 0.2, 1); construction: \"standard\" (default), \"bridge\" or \"pca\", how W(tᵢ) is "
     "built from the normals; s = the number of monitoring times, 1 ≤ s ≤ 1024",
     make_geometric_asian, nullptr, false, false, 0, asian_string_keys},
    {"irradiance_hemisphere", "2π·u₁·L_i(x, ω(u)) on [0,1]², uniform hemisphere map",
     "discontinuous", no_keys, irradiance_keys,
     "occluder: 0 or 1 (default 0), adds default_irradiance_setup's occluder; radiance: L > 0 "
     "(default 1); dimension 2",
     make_irradiance<irradiance_hemisphere>, nullptr, true, false, 2},
    {"irradiance_area", "L·A·V·cosθ·cosθ'/|x − x'|² on [0,1]², light parameters (s, t)",
     "analytic (discontinuous with occluder)", no_keys, irradiance_keys,
     "occluder: 0 or 1 (default 0); radiance: L > 0 (default 1); dimension 2",
     make_irradiance<irradiance_area>, nullptr, true, false, 2},
    // Floating-point stress members (stability_1d.hpp).
    {"shifted_exp", "e^((x − lower)/w)/w on [lower, upper], w = upper − lower; ∫ = e − 1",
     "analytic", no_keys, interval_keys,
     "lower, upper: the interval (default 0, 1), any finite box with a finite width ≥ 2.2e-308; "
     "dimension 1",
     make_interval<shifted_exp_1d>, nullptr, false, false, 1},
    {"cosc_naive", "(1 − cos x)/x² on [0, 1], computed as written (cancellation near 0)",
     "analytic", no_keys, no_keys, "no parameters; dimension 1", make_fixed<cosc_naive_1d>, nullptr,
     false, false, 1},
    {"cosc_stable", "2·sin²(x/2)/x² on [0, 1], the same function without cancellation", "analytic",
     no_keys, no_keys, "no parameters; dimension 1", make_fixed<cosc_stable_1d>, nullptr, false,
     false, 1},
    {"inverse_sqrt", "1/√x on [0, 1], 0 at x = 0", "singular", no_keys, no_keys,
     "no parameters; dimension 1", make_fixed<inverse_sqrt_1d>, nullptr, false, false, 1},
    {"log", "log x on [0, 1], 0 at x = 0", "singular", no_keys, no_keys,
     "no parameters; dimension 1", make_fixed<log_1d>, nullptr, false, false, 1},
    {"exp_float", "eˣ on [lower, upper] evaluated in float", "analytic", no_keys, interval_keys,
     "lower, upper: the interval (default 0, 1), upper ≤ 88.72; dimension 1",
     make_interval<exp_float_1d>, nullptr, false, false, 1},
    {"inverse_quadratic_float", "1/(1 + x²) on [0, 1] evaluated in float", "analytic", no_keys,
     no_keys, "no parameters; dimension 1", make_fixed<inverse_quadratic_float_1d>, nullptr, false,
     false, 1},
}};
}  // namespace

std::optional<key_problem> find_key_problem(const catalogue_entry& e, const integrand_params& p) {
  auto contains = [](std::span<const std::string_view> keys, std::string_view key) {
    return std::find(keys.begin(), keys.end(), key) != keys.end();
  };
  auto list_of = [](std::span<const std::string_view> keys) {
    return keys.empty() ? std::string("none") : fmt::format("{}", fmt::join(keys, ", "));
  };
  const auto string_key_of = [&e](std::string_view key) -> const string_key* {
    for (const string_key& k : e.string_keys) {
      if (k.key == key) return &k;
    }
    return nullptr;
  };
  // "one of \"none\", \"quadratic\", \"exponential\"", the choices as a scene writes them.
  const auto choices_of = [](const string_key& k) {
    std::string out;
    for (std::string_view c : k.choices) out += fmt::format("{}\"{}\"", out.empty() ? "" : ", ", c);
    return fmt::format("one of {}", out);
  };
  std::string parameters =
      fmt::format("arrays: {}; numbers: {}", list_of(e.vector_keys), list_of(e.scalar_keys));
  if (!e.string_keys.empty()) {
    std::vector<std::string_view> names;
    for (const string_key& k : e.string_keys) names.push_back(k.key);
    parameters += fmt::format("; strings: {}", fmt::join(names, ", "));
  }
  const auto unknown = [&](const std::string& key) {
    return key_problem{key, fmt::format("unknown key: not a parameter of {} (its parameters: {})",
                                        e.name, parameters)};
  };
  for (const auto& [key, value] : p.vectors) {
    if (contains(e.vector_keys, key)) continue;
    if (contains(e.scalar_keys, key)) {
      return key_problem{key, fmt::format("expected a number for {}, got an array", e.name)};
    }
    if (const string_key* k = string_key_of(key)) {
      return key_problem{
          key, fmt::format("expected a string, {}, for {}, got an array", choices_of(*k), e.name)};
    }
    return unknown(key);
  }
  for (const auto& [key, value] : p.scalars) {
    if (contains(e.scalar_keys, key)) continue;
    if (contains(e.vector_keys, key)) {
      return key_problem{key,
                         fmt::format("expected an array of numbers for {}, got {}", e.name, value)};
    }
    if (const string_key* k = string_key_of(key)) {
      return key_problem{
          key, fmt::format("expected a string, {}, for {}, got {}", choices_of(*k), e.name, value)};
    }
    return unknown(key);
  }
  for (const auto& [key, value] : p.strings) {
    if (const string_key* k = string_key_of(key)) {
      if (std::find(k->choices.begin(), k->choices.end(), value) != k->choices.end()) continue;
      return key_problem{key, fmt::format("expected {}, got \"{}\"", choices_of(*k), value)};
    }
    if (contains(e.scalar_keys, key)) {
      return key_problem{key, fmt::format("expected a number for {}, got \"{}\"", e.name, value)};
    }
    if (contains(e.vector_keys, key)) {
      return key_problem{
          key, fmt::format("expected an array of numbers for {}, got \"{}\"", e.name, value)};
    }
    return unknown(key);
  }
  return std::nullopt;
}

irradiance_setup make_irradiance_setup(const integrand_params& p) {
  require_fixed_dimension(p, 2, "irradiance");
  const double occluder = scalar_or(p, "occluder", 0.0);
  require(occluder == 0.0 || occluder == 1.0, "occluder", occluder, "0 or 1");
  irradiance_setup setup = default_irradiance_setup(occluder == 1.0);
  setup.radiance = scalar_or(p, "radiance", 1.0);
  return setup;
}

namespace {
// The built-in families, then the added ones (add_integrands).
std::vector<catalogue_entry>& all_entries() {
  static std::vector<catalogue_entry> all(entries.begin(), entries.end());
  return all;
}
}  // namespace

std::span<const catalogue_entry> integrand_catalogue() {
  return all_entries();
}

void add_integrands(std::span<const catalogue_entry> families) {
  for (const catalogue_entry& e : families) {
    if (e.name.empty() || e.make == nullptr) {
      throw std::logic_error(
          fmt::format("add_integrands: the entry '{}' needs a name and a make", e.name));
    }
    if (find_family(e.name) != nullptr) {
      throw std::logic_error(
          fmt::format("add_integrands: integrand '{}' is already in the catalogue", e.name));
    }
    all_entries().push_back(e);
  }
}

const catalogue_entry* find_family(std::string_view name) noexcept {
  for (const auto& e : all_entries()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

std::size_t resolved_dimension(const catalogue_entry& entry, std::size_t dimension) noexcept {
  if (dimension != 0) return dimension;
  return entry.fixed_dimension != 0 ? entry.fixed_dimension : 1;
}

const catalogue_entry& find_catalogue_entry(std::string_view name) {
  if (const catalogue_entry* e = find_family(name)) return *e;
  std::vector<std::string_view> names;
  for (const auto& e : all_entries()) names.push_back(e.name);
  throw invalid_argument("integrand", name, fmt::format("one of {}", fmt::join(names, ", ")));
}

any_integrand make_integrand(std::string_view name, const integrand_params& p) {
  const catalogue_entry& e = find_catalogue_entry(name);
  if (const auto problem = find_key_problem(e, p)) {
    throw invalid_argument::about(problem->key,
                                  fmt::format("invalid {}: {}", problem->key, problem->message));
  }
  if (e.fixed_dimension != 0) require_fixed_dimension(p, e.fixed_dimension, e.name);
  return e.make(p);
}

}  // namespace quadmc
