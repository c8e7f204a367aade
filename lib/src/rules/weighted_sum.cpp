// The kernel of rules/weighted_sum.hpp, compiled once: the accumulators of enum summation, the
// chunked parallel fold (core/parallel_reduce.hpp) and the split naive sum
// (core/split_naive_sum.hpp), over the batches that the caller's template code makes
// (detail::batch_source). The header says how it runs and why its bits do not depend on the
// thread or the process count.
#include "quadmc/rules/weighted_sum.hpp"

#include "quadmc/core/batching.hpp"
#include "quadmc/core/chunk_exchange.hpp"
#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/core/split_naive_sum.hpp"
#include "quadmc/core/summation.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {
namespace detail {
namespace {

// The accumulators of enum summation (core/summation.hpp), each a value type with the same
// operations, so the kernel below is one template over them and the default path compiles to
// the same code as before the option existed. add_weighted(w, y) adds the terms w_i·y_i,
// overwriting w with them where the accumulator needs them stored.
struct pairwise_accumulator {
  neumaier_sum sum;
  void add_batch(std::span<const double> terms) noexcept { sum.add(pairwise_sum(terms)); }
  void add_weighted(std::span<double> w, std::span<const double> y) noexcept {
    sum.add(weighted_pairwise_sum(w, y));
  }
  void merge(const pairwise_accumulator& other) noexcept { sum.merge(other.sum); }
  double value() const noexcept { return sum.value(); }
};

// add(running, t) for the terms in order, on a value, out of line: the accumulators that add one
// term at a time call it. Inlined into the kernel, where the accumulator is a captured object
// that `terms` could alias as far as the compiler knows, GCC 12 stored and reloaded the running
// sum every second term, putting store-to-load forwarding into the chain of adds (a 2^28-panel
// naive Simpson cell took 1.87 s instead of 1.64 s). Same operations, so the same bits.
template <class Sum, class Add>
[[gnu::noinline]] Sum add_in_order(Sum running, std::span<const double> terms, Add add) noexcept {
  for (const double t : terms) add(running, t);
  return running;
}

// w_i ← w_i·y_i, then add_batch: the accumulators that add the terms one at a time.
template <class Accumulator>
void multiply_then_add(Accumulator& acc, std::span<double> w, std::span<const double> y) noexcept {
  for (std::size_t i = 0; i < w.size(); ++i) w[i] *= y[i];
  acc.add_batch(std::span<const double>(w));
}

struct neumaier_accumulator {
  neumaier_sum sum;
  void add_batch(std::span<const double> terms) noexcept {
    sum = add_in_order(sum, terms, [](neumaier_sum& s, double t) { s.add(t); });
  }
  void add_weighted(std::span<double> w, std::span<const double> y) noexcept {
    multiply_then_add(*this, w, y);
  }
  void merge(const neumaier_accumulator& other) noexcept { sum.merge(other.sum); }
  double value() const noexcept { return sum.value(); }
};

struct long_double_accumulator {
  long double sum = 0.0L;
  void add_batch(std::span<const double> terms) noexcept {
    sum = add_in_order(sum, terms, [](long double& s, double t) { s += t; });
  }
  void add_weighted(std::span<double> w, std::span<const double> y) noexcept {
    multiply_then_add(*this, w, y);
  }
  void merge(const long_double_accumulator& other) noexcept { sum += other.sum; }
  double value() const noexcept { return static_cast<double>(sum); }
};

// One double carried through every term in index order: the kernel runs its chunks serially and
// hands each chunk the running sum, so this is exactly Σ left to right, never re-associated.
struct naive_accumulator {
  double sum = 0.0;
  void add_batch(std::span<const double> terms) noexcept {
    sum = add_in_order(sum, terms, [](double& s, double t) { s += t; });
  }
  void add_weighted(std::span<double> w, std::span<const double> y) noexcept {
    multiply_then_add(*this, w, y);
  }
  double value() const noexcept { return sum; }
};

}  // namespace
}  // namespace detail

// A chunk of the kernel below returns its whole sum and writes nothing else, so a cell split
// across processes may share these chunk results (core/chunk_exchange.hpp).
template <>
inline constexpr bool shareable_chunk_result<detail::pairwise_accumulator> = true;
template <>
inline constexpr bool shareable_chunk_result<detail::neumaier_accumulator> = true;
template <>
inline constexpr bool shareable_chunk_result<detail::long_double_accumulator> = true;

namespace detail {

bool accumulator_shares_chunks(summation accumulate) noexcept {
  switch (accumulate) {
    case summation::pairwise:
      return shareable_chunk_result<pairwise_accumulator>;
    case summation::neumaier:
      return shareable_chunk_result<neumaier_accumulator>;
    case summation::long_double:
      return shareable_chunk_result<long_double_accumulator>;
    case summation::naive:
      return true;  // split exactly by split_naive_sum (core/split_naive_sum.hpp)
  }
  return false;
}

rule_result weighted_sum_of_batches(const integrand_info& info, std::uint64_t total,
                                    batch_source make_batch, value_source make_values,
                                    bool share_chunks, unsigned threads, summation accumulate) {
  const std::size_t s = info.dimension();
  const chunking layout{total, rule_chunk_points};
  const std::size_t block_points = std::min(evaluation_block_points(info.evaluation_block),
                                            static_cast<std::size_t>(rule_chunk_points));

  // Makes chunk c block by block — the set's nodes and weights batch by batch, the integrand's
  // values once per block, checked finite — and hands each batch to use(first, w, y). Buffers
  // once per chunk, never per point; one batch (the default block) stays in L1.
  auto evaluate_chunk = [&](std::size_t c, auto&& use) {
    std::vector<double> x(block_points * s);
    std::vector<double> y(block_points);
    std::vector<double> w(block_points);
    for_each_block(layout, c, block_points, [&](std::uint64_t first, std::size_t count) {
      for_each_batch_of(count, [&](std::size_t offset, std::size_t k) {
        make_batch(first + offset, std::span<double>(x.data() + offset * s, k * s),
                   std::span<double>(w.data() + offset, k));
      });
      const std::span<const double> xs(x.data(), count * s);
      const std::span<double> ys(y.data(), count);
      make_values(xs, ys);
      check_finite_batch(info.name, xs, ys, s);
      for_each_batch_of(count, [&](std::size_t offset, std::size_t k) {
        use(first + offset, std::span<double>(w.data() + offset, k),
            std::span<const double>(y.data() + offset, k));
      });
    });
  };

  // Adds the terms of chunk c to `sum` (a fresh accumulator, or the running one for naive).
  auto chunk_sum = [&](std::size_t c, auto sum) {
    evaluate_chunk(c, [&](std::uint64_t, std::span<double> w, std::span<const double> y) {
      sum.add_weighted(w, y);
    });
    return sum;
  };

  // Chunk c's terms w·f in order (rounded as multiply_then_add rounds them) into `out`, for the
  // naive sum split across processes. Only the products go to `out`: generating into it
  // directly, outside L1, slowed the walk by half.
  auto chunk_terms = [&](std::size_t c, std::span<double> out) {
    evaluate_chunk(c, [&](std::uint64_t first, std::span<double> w, std::span<const double> y) {
      double* const products = out.data() + (first - layout.begin(c));
      for (std::size_t i = 0; i < w.size(); ++i) products[i] = w[i] * y[i];
    });
  };

  auto reduce = [&]<class Accumulator>(Accumulator init) {
    if (share_chunks) {
      return parallel_reduce(
          layout.chunks(), threads, init,
          [&](std::size_t c) { return chunk_sum(c, Accumulator{}); },
          [](Accumulator& acc, const Accumulator& part) { acc.merge(part); });
    } else {
      using local = process_local<Accumulator>;
      return parallel_reduce(
                 layout.chunks(), threads, local{init},
                 [&](std::size_t c) { return local{chunk_sum(c, Accumulator{})}; },
                 [](local& acc, const local& part) { acc.value.merge(part.value); })
          .value;
    }
  };

  double sum = 0.0;
  switch (accumulate) {
    case summation::pairwise:
      sum = reduce(pairwise_accumulator{}).value();
      break;
    case summation::neumaier:
      sum = reduce(neumaier_accumulator{}).value();
      break;
    case summation::long_double:
      sum = reduce(long_double_accumulator{}).value();
      break;
    case summation::naive: {
      chunk_exchange* const group = active_chunk_exchange();
      if (share_chunks && group != nullptr && group->size() > 1) {
        sum = split_naive_sum(*group, layout, threads, chunk_terms);
        break;
      }
      naive_accumulator running;
      for (std::size_t c = 0; c < layout.chunks(); ++c) running = chunk_sum(c, running);
      sum = running.value();
      break;
    }
  }

  rule_result result;
  result.value = info.domain.volume() * sum;
  result.evaluations = total;
  return result;
}

}  // namespace detail
}  // namespace quadmc
