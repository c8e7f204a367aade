// Rules that stop sampling when an error claim falls below a tolerance ε
// (docs/theory.md#stopping-rules): the `stopping` of a method run with control = "tolerance".
//
//   replicate_stopping   R independent randomizations of an extensible set, N doubled until the
//                        Student-t half-width t(1 − α/2, R − 1)·inflate·s_R/√R of the R means is
//                        ≤ ε (QMCPy's CubQMCRepStudentT; [L'Ecuyer et al. 2023]).
//   guaranteed_digital   one digitally randomized net, N doubled until C·2^−m·S̃(m) ≤ ε, S̃ the sum
//                        of 2^(m−r−1) of the discrete Walsh coefficients of the values, picked by
//                        the coefficient map of [Hickernell & Jiménez Rugama 2016] (cubSobol_g).
//   guaranteed_lattice   the same on a shifted rank-1 lattice with the discrete Fourier
//                        coefficients ([Jiménez Rugama & Hickernell 2016], cubLattice_g).
//   clt_stopping         two stages: a pilot of n_init points estimates σ, then
//                        n = max(n_init, ⌈(z·inflate·σ̂/ε)²⌉) new points (CubMCCLT).
//   guaranteed_mc        two stages with a Berry–Esseen sample size from a kurtosis bound
//                        ([Hickernell, Jiang, Liu & Owen 2013], CubMCG, absolute tolerance).
//
// Use them through the methods (methods/stopping.cpp), which give each rule its set's values.
// The claims differ in kind and the reliability table audits each: the replicate and CLT rules
// claim a 1 − α confidence interval under a normal approximation; the guaranteed rules claim a
// bound that holds for every f in their cone (the digital and lattice ones) or with probability
// ≥ 1 − α for every f of bounded kurtosis (guaranteed_mc). Not for s where the set has no
// extension (jittered points must be redrawn at every N; their methods use clt_stopping only).
//
// Every rule counts each evaluation it spent (pilots included) and says whether it met ε or ran
// out of its budget n_max first; with the budget exhausted the claim is reported as it stands,
// never replaced by ε.
#pragma once

#include "quadmc/core/function_ref.hpp"

#include <complex>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace quadmc {

struct stopped_estimate {
  double value = std::numeric_limits<double>::quiet_NaN();
  double claimed_error = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t evaluations = 0;  // every value of f spent, pilots and replicates included
  std::uint64_t points = 0;       // N of the final estimate (per replicate for the replicate rule)
  bool met = false;               // claimed_error ≤ tolerance; false: the budget ran out first
};

// f (times the volume, on f's box) at points first … first + y.size() − 1 of randomization
// `replicate` of an extensible set, in the set's extension order (a digital net: natural index;
// the lattice: radical-inverse order, sampling/rank1_lattice_sequence.hpp).
using extension_values =
    function_ref<void(std::uint64_t replicate, std::uint64_t first, std::span<double> y)>;

// Parameters as QMCPy names them, with its defaults.
struct replicate_stopping_options {
  double tolerance = 1e-2;
  std::uint64_t replications = 16;               // R ≥ 2
  std::uint64_t n_init = 256;                    // per replicate, a power of two
  std::uint64_t n_max = std::uint64_t{1} << 30;  // per replicate, a power of two ≥ n_init
  double alpha = 0.01;
  double inflate = 1.0;
};
stopped_estimate replicate_stopping(extension_values values, const replicate_stopping_options& o);

struct guaranteed_qmc_options {
  double tolerance = 1e-2;
  std::uint64_t n_init = 1024;                   // 2^m_min, m_min ≥ r_lag + 1
  std::uint64_t n_max = std::uint64_t{1} << 30;  // a power of two ≥ n_init
  double fudge = 5.0;                            // C of the inflation factor C·2^−m
  unsigned r_lag = 4;  // r: S̃ sums the coefficients 2^(m−r−1) … 2^(m−r)−1
};
stopped_estimate guaranteed_digital(extension_values values, const guaranteed_qmc_options& o);
stopped_estimate guaranteed_lattice(extension_values values, const guaranteed_qmc_options& o);

// One stage of a two-stage rule: an estimate over n new points of stage `stage` (0: the pilot,
// 1: the final sample), with the set's own standard error.
struct stage_estimate {
  double value = std::numeric_limits<double>::quiet_NaN();
  double std_error = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t evaluations = 0;  // the set may round n up to a count it holds
};
using stage_run = function_ref<stage_estimate(std::uint64_t stage, std::uint64_t n)>;

struct two_stage_options {
  double tolerance = 1e-2;
  std::uint64_t n_init = 1024;
  std::uint64_t n_max = 10'000'000'000;  // pilot and final sample together
  double alpha = 0.01;
  double inflate = 1.2;
};
stopped_estimate clt_stopping(stage_run run, const two_stage_options& o);
stopped_estimate guaranteed_mc(stage_run run, const two_stage_options& o);

// --- the pieces, for the tests -----------------------------------------------------------------

// In place: the discrete Walsh (digital) or Fourier (lattice, input in radical-inverse order)
// transform of y, normalized by 1/n, over butterfly levels [from_level, to_level).
void walsh_butterflies(std::span<double> y, unsigned from_level, unsigned to_level) noexcept;
void fourier_butterflies(std::span<std::complex<double>> y, unsigned from_level,
                         unsigned to_level) noexcept;

// The coefficient map of the guaranteed rules: kappa[k] is the index of the coefficient that
// stands for wavenumber class k. `magnitude(i)` is |ŷ_i|.
class coefficient_map {
 public:
  coefficient_map(unsigned m, function_ref<double(std::uint64_t)> magnitude);
  // After a doubling to 2^(m+1) coefficients: the old map and its copy shifted by 2^m, then the
  // top r_lag levels re-sorted.
  void extend(unsigned r_lag, function_ref<double(std::uint64_t)> magnitude);
  std::span<const std::uint64_t> kappa() const noexcept { return kappa_; }
  unsigned m() const noexcept { return m_; }

 private:
  void sort_level(unsigned l, function_ref<double(std::uint64_t)> magnitude);
  std::vector<std::uint64_t> kappa_;
  unsigned m_ = 0;
};

// The Berry–Esseen sample size of guaranteed_mc: n for an absolute tolerance ε over σ_up = ε/r
// (toloversig = r) at uncertainty α with the kurtosis bound, capped at n_budget, and the error
// the n it returns guarantees (in units of σ_up).
struct berry_esseen_size {
  double n = 0;
  double error_over_sigma = 0;
};
berry_esseen_size berry_esseen_sample_size(double toloversig, double alpha, double kurtosis_max,
                                           double n_budget);

}  // namespace quadmc
