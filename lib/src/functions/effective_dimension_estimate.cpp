// estimate_effective_dimensions (functions/effective_dimension_estimate.hpp): the pick-freeze
// estimators of docs/theory.md#estimated-effective-dimension over two Philox samples A and B.
//
// Every share is R or 1 − R with R = ū/w̄, a ratio of means over the same rows i:
//   w_i = ((f(A_i) − m)² + (f(B_i) − m)²)/2, whose mean is σ̂² (m: the mean of all 2n values);
//   truncation at d: u_i = (f(A_i) − f(A_{i,≤d}, B_{i,>d}))²/2, E u = σ² − Σ_{∅≠v⊆{1..d}} σ²_v;
//   first order:     u_i = (f(B_i) − m)·Σⱼ (f(A_i with xⱼ from B_i) − f(A_i)), E u = Σⱼ σ²_{j};
//   mean dimension:  u_i = Σⱼ (f(A_i) − f(A_i with xⱼ from B_i))²/2, E u = Σ_u |u|·σ²_u.
// The delta method gives R's standard error, sd(u − R·w)/(w̄·√n).
#include "quadmc/functions/effective_dimension_estimate.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/normal_quantile.hpp"
#include "quadmc/core/rng.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

namespace quadmc {

namespace {

constexpr std::size_t rows_per_batch = 256;

// R = ū/w̄ over the first u.size() rows, with its interval at z standard errors.
estimated_share ratio(std::span<const double> u, std::span<const double> w, double z) {
  const auto n = static_cast<double>(u.size());
  double u_sum = 0.0, w_sum = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    u_sum += u[i];
    w_sum += w[i];
  }
  const double r = u_sum / w_sum;
  double squares = 0.0;  // Σ (u − R·w)², whose mean is 0 at R = ū/w̄
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double e = u[i] - r * w[i];
    squares += e * e;
  }
  const double half = z * std::sqrt(squares / (n - 1.0) / n) / (w_sum / n);
  return {r, r - half, r + half};
}

estimated_share one_minus(const estimated_share& r) {
  return {1.0 - r.value, 1.0 - r.high, 1.0 - r.low};
}

// The estimate and its interval cut to the range the true value has ([0, 1] for a share, [1, s]
// for the mean dimension): the cut interval covers whenever the uncut one does.
estimated_share within(estimated_share e, double low, double high) {
  e.value = std::clamp(e.value, low, high);
  e.low = std::clamp(e.low, low, high);
  e.high = std::clamp(e.high, low, high);
  return e;
}
class pick_freeze {
 public:
  pick_freeze(const any_integrand& f, std::uint64_t seed)
      : f_(f),
        s_(f.dimension()),
        a_(seed, stream_id({name_id("effective dimension"), 0})),
        b_(seed, stream_id({name_id("effective dimension"), 1})),
        a_rows_(rows_per_batch * s_),
        b_rows_(rows_per_batch * s_),
        x_(rows_per_batch * s_),
        y_(rows_per_batch) {}

  std::uint64_t evaluations() const noexcept { return evaluations_; }

  // f at rows 0 … rows − 1 whose columns j < d come from A and the rest from B (d = s: A alone,
  // d = 0: B alone).
  std::vector<double> values_at(std::size_t d, std::size_t rows) {
    std::vector<double> out(rows);
    for (std::size_t first = 0; first < rows; first += rows_per_batch) {
      const std::size_t m = std::min(rows_per_batch, rows - first);
      load(first, m);
      for (std::size_t i = 0; i < m; ++i) {
        for (std::size_t j = 0; j < s_; ++j) {
          x_[i * s_ + j] = j < d ? a_rows_[i * s_ + j] : b_rows_[i * s_ + j];
        }
      }
      evaluate(m, std::span(out).subspan(first, m));
    }
    return out;
  }

  // For each row i < rows and each column j: f at A_i with xⱼ from B_i, handed to
  // sink(i, j, value) row by row.
  template <class Sink>
  void for_each_swap(std::size_t rows, Sink&& sink) {
    for (std::size_t first = 0; first < rows; first += rows_per_batch) {
      const std::size_t m = std::min(rows_per_batch, rows - first);
      load(first, m);
      for (std::size_t j = 0; j < s_; ++j) {
        std::copy_n(a_rows_.begin(), m * s_, x_.begin());
        for (std::size_t i = 0; i < m; ++i) x_[i * s_ + j] = b_rows_[i * s_ + j];
        evaluate(m, std::span(y_).first(m));
        for (std::size_t i = 0; i < m; ++i) sink(first + i, j, y_[i]);
      }
    }
  }

 private:
  void load(std::size_t first, std::size_t m) {
    a_.fill_uniform(first * s_, std::span(a_rows_).first(m * s_));
    b_.fill_uniform(first * s_, std::span(b_rows_).first(m * s_));
  }
  void evaluate(std::size_t m, std::span<double> y) {
    f_.evaluate(std::span<const double>(x_).first(m * s_), y);
    evaluations_ += m;
  }

  const any_integrand& f_;
  std::size_t s_;
  random_stream a_, b_;
  std::vector<double> a_rows_, b_rows_, x_, y_;
  std::uint64_t evaluations_ = 0;
};

bool all_finite(std::span<const double> v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

}  // namespace

std::optional<effective_dimension_estimate> estimate_effective_dimensions(
    const any_integrand& f, std::uint64_t seed, const effective_dimension_estimate_options& o) {
  require(o.samples >= 2, "samples", o.samples, "at least 2 rows");
  require(o.share > 0.0 && o.share <= 1.0, "share", o.share,
          "a fraction of the variance in (0, 1]");
  require(o.confidence > 0.0 && o.confidence < 1.0, "confidence", o.confidence,
          "a probability in (0, 1)");
  const std::size_t s = f.dimension();
  const std::size_t n = o.samples;
  if (s < 2) return std::nullopt;
  const double z = normal_quantile(0.5 + 0.5 * o.confidence);
  pick_freeze sample(f, seed);

  const std::vector<double> fa = sample.values_at(s, n);
  const std::vector<double> fb = sample.values_at(0, n);
  if (!all_finite(fa) || !all_finite(fb)) return std::nullopt;
  double mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) mean += fa[i] + fb[i];
  mean /= static_cast<double>(2 * n);
  std::vector<double> w(n);
  double variance = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    w[i] = 0.5 * ((fa[i] - mean) * (fa[i] - mean) + (fb[i] - mean) * (fb[i] - mean));
    variance += w[i];
  }
  variance /= static_cast<double>(n);
  if (!(variance > 0.0) || !std::isfinite(variance)) return std::nullopt;

  effective_dimension_estimate out;
  out.share = o.share;
  out.confidence = o.confidence;
  out.samples = n;
  out.variance = variance;

  // The closed share of x₁…x_d, each d evaluated once; at d = s it is 1 (the hybrid is A).
  std::map<std::size_t, estimated_share> closed;
  bool finite = true;
  const auto closed_share = [&](std::size_t d) -> estimated_share {
    if (d == s) return {1.0, 1.0, 1.0};
    if (const auto it = closed.find(d); it != closed.end()) return it->second;
    const std::vector<double> fc = sample.values_at(d, n);
    finite = finite && all_finite(fc);
    std::vector<double> u(n);
    for (std::size_t i = 0; i < n; ++i) u[i] = 0.5 * (fa[i] - fc[i]) * (fa[i] - fc[i]);
    return closed[d] = within(one_minus(ratio(u, w, z)), 0.0, 1.0);
  };
  // The smallest d in [1, s] whose share passes, by bisection (pass(s) holds: the share is 1). The
  // same tolerance as the exact form's: a share that is q up to rounding counts.
  const auto first_passing = [&](auto pass) {
    std::size_t low = 1, high = s;
    while (low < high) {
      const std::size_t mid = low + (high - low) / 2;
      if (pass(closed_share(mid))) {
        high = mid;
      } else {
        low = mid + 1;
      }
    }
    return low;
  };
  const double q = o.share - 1e-12;
  out.first_coordinate = closed_share(1);
  out.truncation = first_passing([&](const estimated_share& e) { return e.value >= q; });
  out.truncation_low = first_passing([&](const estimated_share& e) { return e.high >= q; });
  out.truncation_high = first_passing([&](const estimated_share& e) { return e.low >= q; });

  const auto s64 = static_cast<std::uint64_t>(s);
  const std::size_t rows =
      static_cast<std::size_t>(std::min<std::uint64_t>(n, o.first_order_coordinates / s64 / s64));
  if (rows >= 64) {
    std::vector<double> first(rows, 0.0), total(rows, 0.0);
    sample.for_each_swap(rows, [&](std::size_t i, std::size_t, double value) {
      finite = finite && std::isfinite(value);
      first[i] += value - fa[i];
      total[i] += 0.5 * (fa[i] - value) * (fa[i] - value);
    });
    for (std::size_t i = 0; i < rows; ++i) first[i] *= fb[i] - mean;
    const std::span<const double> w_rows = std::span<const double>(w).first(rows);
    out.first_order = within(ratio(first, w_rows, z), 0.0, 1.0);
    out.mean_dimension = within(ratio(total, w_rows, z), 1.0, static_cast<double>(s));
    out.first_order_samples = rows;
    out.superposition_low = out.first_order->high < q ? 2 : 1;
    out.superposition_high = out.first_order->low >= q ? 1 : 0;
  }
  if (!finite) return std::nullopt;
  out.evaluations = sample.evaluations();
  return out;
}

}  // namespace quadmc
