// mybench: quadmc's command with two integrand families and a method of this project's own.
//   mybench list            the catalogue and the registry, with sum_squared, gaussian_of_sum and
//                           antithetic_mc among them
//   mybench run my.toml     their convergence beside Simpson and plain Monte Carlo
#include <quadmc/command.hpp>
#include <quadmc/core/rng.hpp>
#include <quadmc/core/welford.hpp>
#include <quadmc/functions/catalogue.hpp>
#include <quadmc/methods/registry.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace {

// f(x) = (x₁ + … + x_s)² on [0,1]^s. Its integral is s·E[x²] + s(s − 1)·E[x]² = s/3 + s(s − 1)/4.
struct sum_squared {
  std::size_t s;
  std::size_t dimension() const { return s; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    for (std::size_t i = 0; i < y.size(); ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j < s; ++j) sum += x[i * s + j];
      y[i] = sum * sum;
    }
  }
  quadmc::integrand_info info() const {
    const double n = static_cast<double>(s);
    quadmc::integrand_info out;
    out.name = "sum_squared";
    out.formula = "(x₁ + … + x_s)² on [0,1]^s";
    out.domain = quadmc::box::unit(s);
    out.exact = n / 3 + n * (n - 1) / 4;  // NaN where no closed form is known
    out.reference = "closed form";
    out.regularity = quadmc::smoothness::analytic;
    return out;
  }
};

// g(x) = exp(−(x₁ + … + x_s)²/s), whose integral has no closed form here: its scene gives
// `reference = "computed"`, and the plan computes it (README "Your own points, rules and
// integrands").
struct gaussian_of_sum {
  std::size_t s;
  std::size_t dimension() const { return s; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    sum_squared{s}.evaluate(x, y);
    for (double& v : y) v = std::exp(-v / static_cast<double>(s));
  }
  quadmc::integrand_info info() const {
    quadmc::integrand_info out = sum_squared{s}.info();
    out.name = "gaussian_of_sum";
    out.formula = "exp(−(x₁ + … + x_s)²/s) on [0,1]^s";
    out.exact = NAN;
    out.reference = "no closed form";
    return out;
  }
};

template <class F>
quadmc::any_integrand make(const quadmc::integrand_params& p) {
  return quadmc::any_integrand(F{std::max<std::size_t>(p.dimension, 1)});
}

const std::array<quadmc::catalogue_entry, 2> integrands{{
    {"sum_squared",
     "(x₁ + … + x_s)² on [0,1]^s",
     "analytic",
     {},
     {},
     "no parameters",
     make<sum_squared>},
    {"gaussian_of_sum",
     "exp(−(x₁ + … + x_s)²/s) on [0,1]^s",
     "analytic",
     {},
     {},
     "no parameters; no exact value: give reference",
     make<gaussian_of_sum>},
}};

// Antithetic Monte Carlo: the mean of (f(u) + f(1 − u))/2 over N/2 independent uniform u, each
// pair one sample of the variance estimate. Exact on f linear in x; O(N^(−1/2)) otherwise.
class antithetic_mc final : public quadmc::method {
 public:
  using method::method;
  quadmc::sizing size_for(std::uint64_t N, std::size_t) const override {
    if (N < 2) return {std::nullopt, "N < 2: no antithetic pair"};
    return {quadmc::cell_size{N - N % 2}, {}};
  }
  quadmc::theoretical_rate theory(const quadmc::integrand_class& f) const override {
    return quadmc::root_n_rate(f, "σ²/N of the pairs' means", "mybench.cpp");
  }
  quadmc::repetition_result run(const quadmc::method_cell& cell,
                                const quadmc::run_context& context) const override {
    const std::size_t s = cell.function.dimension();
    const quadmc::random_stream random(context.seed, cell.stream);
    constexpr std::size_t batch = 256;  // pairs per call of the integrand
    std::vector<double> x(2 * batch * s), y(2 * batch);
    quadmc::welford pairs;
    const std::uint64_t total = cell.size.evaluations / 2;
    for (std::uint64_t first = 0; first < total; first += batch) {
      const std::size_t m = static_cast<std::size_t>(std::min<std::uint64_t>(batch, total - first));
      for (std::size_t k = 0; k < m * s; ++k) {
        x[k] = random.uniform(first * s + k);
        x[m * s + k] = 1.0 - x[k];
      }
      cell.function.evaluate({x.data(), 2 * m * s}, {y.data(), 2 * m});
      for (std::size_t i = 0; i < m; ++i) pairs.add(0.5 * (y[i] + y[m + i]));
    }
    quadmc::repetition_result out;
    out.value = pairs.mean();
    out.std_error = out.error_estimate = pairs.std_error();
    out.evaluations = 2 * total;
    return out;
  }
};

constexpr std::array<quadmc::cell_control, 1> fixed{quadmc::cell_control::fixed_size};
const std::array<quadmc::method_descriptor, 1> methods{{
    {"antithetic_mc",
     "antithetic Monte Carlo: pairs u, 1 − u",
     quadmc::method_kind::randomized,
     {},
     fixed,
     [](const quadmc::method_descriptor& d, quadmc::option_reader&)
         -> std::unique_ptr<const quadmc::method> { return std::make_unique<antithetic_mc>(d); }},
}};

}  // namespace

int main(int argc, char** argv) {
  quadmc::add_integrands(integrands);
  quadmc::add_methods(methods);
  return quadmc::command_main(argc, argv, "mybench");
}
