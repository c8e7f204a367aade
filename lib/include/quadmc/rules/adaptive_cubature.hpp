// h-adaptive cubature with the Genz–Malik rule (genz_malik_rule.hpp): integrate the box, then
// repeatedly bisect the regions of largest error estimate along their axis of largest fourth
// difference, until the summed error estimate is below a tolerance or the evaluation budget is
// spent ([Genz & Malik 1980]; [Berntsen, Espelid & Genz 1991]).
//
// Use it for smooth integrands in 2 ≤ s ≲ 10 when an error estimate is wanted with the value:
// it is the algorithm of [cubature]'s hcubature and Cuba's Cuhre. Not for s = 1 (the rule needs
// s ≥ 2), not for s ≳ 12 (2^s + 2s² + 2s + 1 evaluations per region: Monte Carlo wins), and not
// where the error estimate matters on discontinuous or sharply peaked integrands: |Q₇ − Q₅| sees
// only what falls between its nodes (the reliability scene measures how often it is wrong).
//
// Which regions a round splits (the parallel variant of [Gladwell 1987] that hcubature_v uses, so
// that evaluation counts are comparable with it):
//  - tolerance τ > 0: pop regions in decreasing error until the errors of those not popped sum to
//    at most τ — the fewest splits that could meet τ if the children were exact;
//  - budget only (τ = 0): pop until the rest carry at most half the total estimate, so each round
//    aims to halve the error (hcubature_v with τ = 0 would split every region each round, which
//    refines uniformly and wastes the budget on regions already accurate).
// A split costs 2·points() evaluations and is made only while the budget holds both children, so
// a run never spends more than max_evaluations (hcubature checks before a split and can end up to
// 2·points() − 1 above its maxEval).
//
// Batches and threads: the children of a round are evaluated together, their nodes generated
// region after region in batches of batch_points = 256 (one integrand call per batch, one virtual
// call through any_integrand), in chunks of whole regions (⌈2^14 / points()⌉ regions, at least
// one) that quadmc::parallel_reduce runs on the threads. Each region's estimate depends only on
// its own values, summed in node order, and every decision (which regions to split, the running
// totals, the final sums over the regions in creation order, Neumaier-compensated) is made on
// one thread in a fixed order: the result is bitwise the same for any thread count.
//
// Memory: 8·(2s + 6) bytes per region (its box, estimate, volume and heap entry); the store is
// capped at 512 MiB of regions, after which the run stops refining and says it did not converge
// (a budget of 2^30 evaluations in s = 2 would otherwise hold 3·10^7 regions, 3 GiB). A thread
// keeps the storage of its last run, up to 1 MiB, for its next one (detail::workspace_lease): a
// run to 10⁻³ in s = 2 or 4 takes a few microseconds, and its eleven allocations were 13 % of
// the instructions of one in s = 2 (callgrind, 51 evaluations). What a run computes never
// depends on what the storage held before.
#pragma once

#include "quadmc/core/batching.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/rules/genz_malik_rule.hpp"
#include "quadmc/rules/rule_result.hpp"
#include "quadmc/rules/weighted_sum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

namespace quadmc {

struct adaptive_cubature_options {
  std::uint64_t max_evaluations = 0;  // at least one region's points(); never exceeded
  double absolute_tolerance = 0.0;    // > 0: stop once the error estimate is ≤ it; 0: the budget
  unsigned threads = 1;               // 0 = all cores; the result does not depend on it
};

struct adaptive_cubature_result : rule_result {
  std::uint64_t regions = 0;
  // The estimate reached the tolerance (always false with absolute_tolerance = 0, unless every
  // region's estimate is exactly 0).
  bool converged = false;
};

// The most regions the store holds in s dimensions (512 MiB, see above).
inline std::uint64_t adaptive_cubature_max_regions(std::size_t s) noexcept {
  return (std::uint64_t{1} << 29) / (8 * (2 * static_cast<std::uint64_t>(s) + 6));
}

namespace detail {

// The regions of one run: boxes as (centre, half-width) rows of 2s doubles, their volumes
// (halved exactly at each split) and their estimates, indexed by creation order.
struct cubature_regions {
  std::size_t s = 0;
  std::vector<double> boxes;
  std::vector<double> volumes;
  std::vector<genz_malik_estimate> estimates;

  std::span<const double> centre(std::size_t r) const noexcept {
    return {boxes.data() + 2 * s * r, s};
  }
  std::span<const double> half_width(std::size_t r) const noexcept {
    return {boxes.data() + 2 * s * r + s, s};
  }
  std::size_t size() const noexcept { return volumes.size(); }
};

// What require_integration_box (weighted_sum.hpp) accepts, checked without formatting its
// messages: finite bounds, lower ≤ upper, finite widths.
inline bool is_integration_box(const box& domain) noexcept {
  if (domain.upper.size() != domain.lower.size()) return false;
  for (std::size_t j = 0; j < domain.lower.size(); ++j) {
    const double a = domain.lower[j];
    const double b = domain.upper[j];
    if (!std::isfinite(a) || !std::isfinite(b) || !(a <= b) || !std::isfinite(b - a)) return false;
  }
  return true;
}

// A buffer of doubles that grows but is never zero-filled: every element is written before it
// is read (nodes, then values), and a std::vector's resize would clear 256·s doubles of points
// per call — measured by callgrind as 13% of a run to 10⁻³ in s = 2 (85 evaluations).
class scratch_buffer {
 public:
  double* ensure(std::size_t n) {
    if (n > capacity_) {
      data_ = std::make_unique_for_overwrite<double[]>(n);
      capacity_ = n;
    }
    return data_.get();
  }
  std::size_t capacity() const noexcept { return capacity_; }

 private:
  std::unique_ptr<double[]> data_;
  std::size_t capacity_ = 0;
};

// Buffers one chunk of regions needs: the values of its nodes and one batch of points. A run
// keeps one for the rounds that fit in a single chunk (most rounds of a run to a tolerance split a
// few regions), so those allocate nothing; larger rounds allocate one per chunk.
struct chunk_buffers {
  scratch_buffer values;
  scratch_buffer x;
};

// A region's place in the heap: largest error first, equal errors by larger index (a fixed order,
// whatever the threads), kept with std::push_heap / std::pop_heap and std::less, which is what
// std::priority_queue does with its default comparison, so the regions pop in the same order.
using region_heap_entry = std::pair<double, std::uint32_t>;

// All a run allocates: its regions, the heap, the lists of a round and the buffers of a chunk.
struct cubature_workspace {
  cubature_regions store;
  std::vector<region_heap_entry> heap;
  std::vector<std::uint32_t> split;
  std::vector<std::uint32_t> children;
  chunk_buffers chunk;

  // Empty, capacities kept.
  void clear() noexcept {
    store.boxes.clear();
    store.volumes.clear();
    store.estimates.clear();
    heap.clear();
    split.clear();
    children.clear();
  }
  std::size_t capacity_bytes() const noexcept {
    return sizeof(double) * (store.boxes.capacity() + store.volumes.capacity() +
                             chunk.values.capacity() + chunk.x.capacity()) +
           sizeof(genz_malik_estimate) * store.estimates.capacity() +
           sizeof(region_heap_entry) * heap.capacity() +
           sizeof(std::uint32_t) * (split.capacity() + children.capacity());
  }
};

// The workspace a thread keeps between runs: empty until its first run, then that run's storage
// if it was at most 1 MiB (larger runs take milliseconds, so their allocations do not show, and a
// thread should not hold on to hundreds of MiB).
inline std::unique_ptr<cubature_workspace>& spare_workspace() noexcept {
  thread_local std::unique_ptr<cubature_workspace> spare;
  return spare;
}

// A run's workspace: the thread's spare one, emptied, if there is one, else a new one; given
// back at the end of the run (or when it throws). A run nested in another on the same thread (an
// integrand that itself integrates) finds no spare and allocates its own. Each thread has its own
// spare, so runs on different threads never share one.
class workspace_lease {
 public:
  static constexpr std::size_t keep_bytes = std::size_t{1} << 20;

  workspace_lease() : work_(std::move(spare_workspace())) {
    if (work_) {
      work_->clear();
    } else {
      work_ = std::make_unique<cubature_workspace>();
    }
  }
  ~workspace_lease() {
    if (work_->capacity_bytes() <= keep_bytes) spare_workspace() = std::move(work_);
  }
  workspace_lease(const workspace_lease&) = delete;
  workspace_lease& operator=(const workspace_lease&) = delete;

  cubature_workspace& operator*() const noexcept { return *work_; }

 private:
  std::unique_ptr<cubature_workspace> work_;
};

// Evaluates the rule on regions ids[first, first + count) into their estimates.
template <integrand F>
void evaluate_chunk(const F& f, std::string_view name, const genz_malik_rule& rule,
                    cubature_regions& store, std::span<const std::uint32_t> ids, std::size_t first,
                    std::size_t count, chunk_buffers& work) {
  const std::size_t s = store.s;
  const std::uint64_t points = rule.points();
  const std::uint64_t total = count * points;
  double* values = work.values.ensure(static_cast<std::size_t>(total));
  // One batch of points, no larger than the chunk (17 points for one region in s = 2).
  double* x =
      work.x.ensure(static_cast<std::size_t>(std::min<std::uint64_t>(batch_points, total)) * s);
  std::size_t region = 0;
  std::uint64_t node = 0;
  for (std::uint64_t start = 0; start < total; start += batch_points) {
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(batch_points, total - start));
    // The batch in runs of consecutive nodes of one region.
    for (std::size_t i = 0; i < n;) {
      const std::uint32_t id = ids[first + region];
      const auto run = static_cast<std::size_t>(std::min<std::uint64_t>(n - i, points - node));
      rule.nodes(node, run, store.centre(id), store.half_width(id), x + i * s);
      i += run;
      node += run;
      if (node == points) {
        node = 0;
        ++region;
      }
    }
    const std::span<const double> xs(x, n * s);
    const std::span<double> ys(values + start, n);
    f.evaluate(xs, ys);
    check_finite_batch(name, xs, ys, s);
  }
  for (std::size_t r = 0; r < count; ++r) {
    const std::uint32_t id = ids[first + r];
    store.estimates[id] =
        rule.combine(std::span<const double>(values + r * points, points), store.volumes[id]);
  }
}

// Evaluates the rule on regions ids[0…) and stores their estimates (see the file comment for the
// batches and chunks).
template <integrand F>
void evaluate_regions(const F& f, std::string_view name, const genz_malik_rule& rule,
                      cubature_regions& store, std::span<const std::uint32_t> ids, unsigned threads,
                      chunk_buffers& work) {
  const std::uint64_t per_chunk = std::max<std::uint64_t>(1, rule_chunk_points / rule.points());
  const chunking layout{ids.size(), per_chunk};
  if (layout.chunks() == 1) {
    parallel_reduce_peak_threads() = std::max(parallel_reduce_peak_threads(), 1u);
    evaluate_chunk(f, name, rule, store, ids, 0, ids.size(), work);
    return;
  }
  auto chunk = [&](std::size_t c) {
    chunk_buffers own;
    const auto first = static_cast<std::size_t>(layout.begin(c));
    evaluate_chunk(f, name, rule, store, ids, first,
                   static_cast<std::size_t>(layout.end(c)) - first, own);
    return 0;
  };
  parallel_reduce(layout.chunks(), threads, 0, chunk, [](int&, const int&) {});
}

}  // namespace detail

// ∫ f over f.info().domain by h-adaptive Genz–Malik cubature. Throws invalid_argument for s < 2
// or s > 40, a budget below one region, a negative or non-finite tolerance or a bad domain;
// non_finite_value if f returns NaN/±inf (naming the point).
template <integrand F>
adaptive_cubature_result genz_malik_cubature(const F& f, const adaptive_cubature_options& options) {
  // A reference, not a copy: any_integrand returns its info by reference, and copying its
  // strings and vectors would cost more than a whole run to 10⁻³ in s = 2 (about 150 points).
  const auto& info = f.info();
  const std::size_t s = f.dimension();
  // The messages are formatted only when a check fails: a run to 10⁻³ takes microseconds, and
  // formatting them every time would be a measurable part of it.
  if (info.domain.dimension() != s) {
    require(false, "integrand domain dimension", info.domain.dimension(),
            fmt::format("the integrand's dimension {}", s));
  }
  if (!detail::is_integration_box(info.domain)) require_integration_box(info.domain);
  const genz_malik_rule rule(s);
  const std::uint64_t points = rule.points();
  if (options.max_evaluations < points) {
    require(false, "max_evaluations", options.max_evaluations,
            fmt::format("at least one region's 2^s + 2s² + 2s + 1 = {} evaluations (s = {})",
                        points, s));
  }
  const double tolerance = options.absolute_tolerance;
  require(std::isfinite(tolerance) && tolerance >= 0.0, "absolute_tolerance", tolerance,
          "a finite tolerance ≥ 0 (0: spend the budget)");
  const std::uint64_t max_regions = adaptive_cubature_max_regions(s);

  // Room for the regions of a small run up front (at most 64, fewer if the budget or the store
  // allows fewer), so that a run to 10⁻³ in a few dimensions, which makes a handful of regions,
  // does not reallocate its vectors as they grow; a workspace kept from the thread's last run
  // (workspace_lease) usually has the room already, and then nothing is allocated at all. Larger
  // runs grow as before; the results do not depend on capacities.
  const std::uint64_t budget_regions = 1 + 2 * ((options.max_evaluations - points) / (2 * points));
  const auto initial_regions =
      static_cast<std::size_t>(std::min({budget_regions, max_regions, std::uint64_t{64}}));
  const detail::workspace_lease lease;
  detail::cubature_workspace& work = *lease;
  detail::cubature_regions& store = work.store;
  store.s = s;
  store.boxes.reserve(2 * s * initial_regions);
  store.volumes.reserve(initial_regions);
  store.estimates.reserve(initial_regions);
  store.boxes.resize(2 * s);
  for (std::size_t j = 0; j < s; ++j) {
    store.boxes[j] = 0.5 * (info.domain.lower[j] + info.domain.upper[j]);
    store.boxes[s + j] = 0.5 * (info.domain.upper[j] - info.domain.lower[j]);
  }
  store.volumes.push_back(info.domain.volume());
  store.estimates.resize(1);
  const std::uint32_t root = 0;
  detail::evaluate_regions(f, info.name, rule, store, std::span<const std::uint32_t>(&root, 1),
                           options.threads, work.chunk);
  std::uint64_t evaluations = points;

  std::vector<detail::region_heap_entry>& heap = work.heap;
  constexpr std::less<detail::region_heap_entry> heap_order{};
  heap.reserve(initial_regions);
  heap.emplace_back(store.estimates[0].error, 0);
  neumaier_sum total_error;
  total_error.add(store.estimates[0].error);

  adaptive_cubature_result result;
  std::vector<std::uint32_t>& split = work.split;
  std::vector<std::uint32_t>& children = work.children;
  split.reserve(initial_regions / 2 + 1);
  children.reserve(initial_regions);
  for (;;) {
    const double total = total_error.value();
    if ((tolerance > 0.0 && total <= tolerance) || total == 0.0) {
      result.converged = true;
      break;
    }
    const double target = tolerance > 0.0 ? tolerance : 0.5 * total;
    double remaining = total;
    split.clear();
    while (!heap.empty() && evaluations + 2 * points <= options.max_evaluations &&
           store.size() + split.size() < max_regions) {
      std::pop_heap(heap.begin(), heap.end(), heap_order);
      const auto [error, id] = heap.back();
      heap.pop_back();
      split.push_back(id);
      remaining -= error;
      evaluations += 2 * points;
      if (remaining <= target) break;
    }
    if (split.empty()) break;  // the budget (or the region store) cannot hold another split
    children.clear();
    for (const std::uint32_t id : split) {
      total_error.add(-store.estimates[id].error);
      const std::size_t axis = store.estimates[id].split_axis;
      const auto child = static_cast<std::uint32_t>(store.size());
      // The new region copies the parent's box; both halve along the split axis.
      store.boxes.resize(store.boxes.size() + 2 * s);
      std::copy_n(store.boxes.begin() + 2 * s * id, 2 * s, store.boxes.begin() + 2 * s * child);
      double* a = store.boxes.data() + 2 * s * id;
      double* b = store.boxes.data() + 2 * s * child;
      const double h = 0.5 * a[s + axis];
      a[s + axis] = h;
      b[s + axis] = h;
      const double c = a[axis];
      a[axis] = c - h;
      b[axis] = c + h;
      store.volumes[id] *= 0.5;
      store.volumes.push_back(store.volumes[id]);
      store.estimates.emplace_back();
      children.push_back(id);
      children.push_back(child);
    }
    detail::evaluate_regions(f, info.name, rule, store, children, options.threads, work.chunk);
    for (const std::uint32_t id : children) {
      total_error.add(store.estimates[id].error);
      heap.emplace_back(store.estimates[id].error, id);
      std::push_heap(heap.begin(), heap.end(), heap_order);
    }
  }

  neumaier_sum value;
  neumaier_sum error;
  for (const genz_malik_estimate& e : store.estimates) {
    value.add(e.value);
    error.add(e.error);
  }
  result.value = value.value();
  result.error_estimate = error.value();
  result.evaluations = evaluations;
  result.regions = store.size();
  return result;
}

}  // namespace quadmc
