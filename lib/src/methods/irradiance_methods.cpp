// The irradiance estimators as methods: directions uniform or cosine-weighted on the hemisphere,
// or points uniform on the light (estimators/irradiance_estimators.hpp), for the rendering
// integrands only, each with its 2D uniforms from any point set (`point_set`), or from a user's
// 2-column files (point_set = "external_points", external.hpp: `path`, `points`).
#include "families.hpp"

#include <fmt/format.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace quadmc::methods {
namespace {

class irradiance_method final : public method {
 public:
  irradiance_method(const method_descriptor& d, irradiance_sampling technique,
                    point_set_choice points)
      : method(d), technique_(technique), points_(points) {}

  std::string label_suffix() const override {
    return points_.given ? fmt::format("_{}", points_.name()) : std::string();
  }

  std::optional<std::string> incompatibility(const integrand_traits& f) const override {
    if (f.rendering) return std::nullopt;
    return fmt::format("{} estimates irradiance; '{}' is not a rendering integrand",
                       descriptor().name, f.family);
  }

  sizing size_for(std::uint64_t N, std::size_t s) const override { return points_.size_for(N, s); }
  std::vector<sizing> explicit_sizes(std::size_t) const override {
    return points_.explicit_sizes();
  }
  std::string explicit_sizes_key() const override { return points_.explicit_sizes_key(); }

  quadmc::error_bars error_bars() const override { return points_.error_bars(); }

  // Uniform-hemisphere, cosine-weighted and light-area sampling are importance sampling with
  // bounded weights: finite variance, so σ/√N; only the constant σ differs
  // (docs/theory.md#irradiance-estimators).
  theoretical_rate theory(const integrand_class& f) const override {
    if (points_.file) return point_file_theory();
    return root_n_rate(f, "importance sampling with bounded f/p: finite variance, σ/√N",
                       "docs/theory.md#irradiance-estimators; [Ramamoorthi 2009, §2.2.3, §4.1]");
  }

  bool shares_chunks() const override { return sample_mean_shares_chunks; }

  void check_inputs(std::size_t, const cell_size& size, std::uint64_t repetitions) const override {
    check_uniform_files(points_, uniforms(), size, repetitions);
  }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    const irradiance_setup setup = make_irradiance_setup(cell.params);
    if (points_.file) {
      const point_file_data u = read_uniform_file(points_, uniforms(), cell);
      return from_estimate(
          irradiance_over_file(technique_, setup, file_points(u), context.threads));
    }
    return from_estimate(points_.set->irradiance(technique_, setup,
                                                 {context.seed, cell.stream, context.rng},
                                                 cell.size.evaluations, context.threads));
  }

 private:
  // A direction or a point on the light takes two u per sample: a file of uniforms has two
  // columns, whatever the integrand's s.
  uniform_use uniforms() const noexcept {
    return {2, descriptor().name, "maps two uniforms to a direction or a light point per sample"};
  }

  irradiance_sampling technique_;
  point_set_choice points_;
};

constexpr std::array<option_doc, 3> option_docs{{
    {"point_set",
     "the pattern of the 2D uniforms (independent [default], jittered, unjittered, "
     "padded_jittered, latin_hypercube, sobol, halton, lattice: their default randomization, "
     "counts mapped as for that method; or external_points: the rows of the files of `path`, 2 "
     "columns, error bars from replicates); the label then gets \"_<point_set>\""},
    {"path",
     "point_set = \"external_points\" only (then required): the file of uniforms per (N, "
     "realization), 2 columns, a template with {N} and {r} as for the external_points method"},
    {"points",
     "point_set = \"external_points\" only: explicit N per cell (an integer or an increasing "
     "list), replacing budget.N"},
}};
constexpr std::array<cell_control, 1> fixed_only{cell_control::fixed_size};

template <irradiance_sampling Technique>
std::unique_ptr<const method> create(const method_descriptor& d, option_reader& r) {
  return std::make_unique<irradiance_method>(d, Technique, read_point_set(r));
}

const std::array<method_descriptor, 3> descriptors{{
    {"irradiance_hemisphere_uniform", "irradiance, directions uniform on the hemisphere",
     method_kind::randomized, option_docs, fixed_only,
     create<irradiance_sampling::uniform_hemisphere>},
    {"irradiance_hemisphere_cosine", "irradiance, cosine-weighted hemisphere directions",
     method_kind::randomized, option_docs, fixed_only,
     create<irradiance_sampling::cosine_hemisphere>},
    {"irradiance_light_area", "irradiance, points uniform on the light's area",
     method_kind::randomized, option_docs, fixed_only, create<irradiance_sampling::light_area>},
}};

}  // namespace

std::span<const method_descriptor> irradiance_methods() noexcept {
  return descriptors;
}

}  // namespace quadmc::methods
