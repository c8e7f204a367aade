// The tables of the nested rules (nested_rule.hpp): Clenshaw–Curtis weights by the exact cosine
// sum, Gauss–Patterson from quadrule, the periodic trapezoid rule in closed form.
#include "quadmc/rules/nested_rule.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <numbers>

// quadrule.h declares C functions without an extern "C" guard of its own.
extern "C" {
#include <quadrule.h>
}

namespace quadmc {
namespace {

constexpr unsigned clenshaw_curtis_levels = 14;
constexpr unsigned patterson_levels = 7;  // 255 nodes: quadrule's largest Patterson table
constexpr unsigned trapezoid_levels = 16;

// Clenshaw–Curtis on [0, 1] with n + 1 nodes t_k = sin²(kπ/(2n)) (= (1 − cos(kπ/n))/2 without the
// cancellation near t = 0), n = 2^l: the weights of [Waldvogel 2006, eq. 2.4] halved for the unit
// interval,
//   w_k = (c_k/(2n))·(1 − Σ_{j=1}^{n/2} b_j·cos(2jkπ/n)/(4j² − 1)),
// c_0 = c_n = 1, c_k = 2 otherwise, b_{n/2} = 1, b_j = 2 otherwise. The cosines come from one
// table of cos(2πm/n) (jk mod n walks it), and the sum is compensated: its terms fall like 1/j²,
// so its rounding stays a few ulp of its O(1) value.
std::vector<double> clenshaw_curtis_weights(std::uint64_t n) {
  std::vector<double> w(n + 1);
  std::vector<double> cosine(n);
  for (std::uint64_t m = 0; m < n; ++m) {
    cosine[m] = std::cos(2.0 * std::numbers::pi * static_cast<double>(m) / static_cast<double>(n));
  }
  const std::uint64_t half = n / 2;
  for (std::uint64_t k = 0; k <= half; ++k) {
    neumaier_sum sum;
    std::uint64_t m = 0;  // j·k mod n
    for (std::uint64_t j = 1; j <= half; ++j) {
      m += k;
      if (m >= n) m -= n;
      const double b = j == half ? 1.0 : 2.0;
      const auto jd = static_cast<double>(j);
      sum.add(b * cosine[m] / (4.0 * jd * jd - 1.0));
    }
    const double c = (k == 0 || k == n) ? 1.0 : 2.0;
    w[k] = c / (2.0 * static_cast<double>(n)) * (1.0 - sum.value());
    w[n - k] = w[k];  // the rule is symmetric; this also makes the two halves bitwise equal
  }
  return w;
}

double clenshaw_curtis_node(std::uint64_t k, std::uint64_t n) {
  const double s =
      std::sin(std::numbers::pi * static_cast<double>(k) / (2.0 * static_cast<double>(n)));
  return s * s;
}

}  // namespace

std::string_view to_string(nested_rule_kind kind) noexcept {
  switch (kind) {
    case nested_rule_kind::clenshaw_curtis:
      return "clenshaw_curtis";
    case nested_rule_kind::gauss_patterson:
      return "gauss_patterson";
    case nested_rule_kind::trapezoid:
      return "trapezoid";
  }
  return "?";
}

std::optional<nested_rule_kind> parse_nested_rule_kind(std::string_view name) noexcept {
  for (const nested_rule_kind k :
       {nested_rule_kind::clenshaw_curtis, nested_rule_kind::gauss_patterson,
        nested_rule_kind::trapezoid}) {
    if (to_string(k) == name) return k;
  }
  return std::nullopt;
}

unsigned nested_rule_max_level(nested_rule_kind kind) noexcept {
  switch (kind) {
    case nested_rule_kind::clenshaw_curtis:
      return clenshaw_curtis_levels;
    case nested_rule_kind::gauss_patterson:
      return patterson_levels;
    case nested_rule_kind::trapezoid:
      return trapezoid_levels;
  }
  return 0;
}

// Appends a level: its nodes listed by id (the previous level's ids first, in their order, then
// the new ones) and their weights in the same order.
void nested_rule::add_level(std::span<const double> nodes_in_birth_order,
                            std::span<const double> weights) {
  const auto level = static_cast<unsigned>(count_.size());
  const std::size_t old = nodes_.size();
  require(nodes_in_birth_order.size() > old,
          fmt::format("{} level {} nodes", to_string(kind_), level), nodes_in_birth_order.size(),
          fmt::format("more than the {} of the level below", old));
  for (std::size_t id = 0; id < old; ++id) {
    // The tables of one level are computed apart from the others: nesting is checked to the
    // last bit but one (quadrule's Patterson tables repeat each node's decimal expansion).
    const double a = nodes_[id];
    const double b = nodes_in_birth_order[id];
    // The message is formatted only on failure: building it for each of the ~33 000 nodes
    // cost more than the tables themselves.
    if (std::abs(a - b) >
        2.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), 1e-300)) {
      require(false, fmt::format("{} level {} node {}", to_string(kind_), level, id), b,
              fmt::format("the node {} of level {} (nested rules)", quote(a), level - 1));
    }
  }
  for (std::size_t id = old; id < nodes_in_birth_order.size(); ++id) {
    nodes_.push_back(nodes_in_birth_order[id]);
    birth_.push_back(level);
  }
  count_.push_back(nodes_.size());
  weight_offset_.push_back(weights_.size());
  weights_.insert(weights_.end(), weights.begin(), weights.end());
}

nested_rule::nested_rule(nested_rule_kind kind) : kind_(kind) {
  const unsigned levels = nested_rule_max_level(kind);
  switch (kind) {
    case nested_rule_kind::clenshaw_curtis: {
      // Level 0 is the midpoint rule; level l ≥ 1 has n = 2^l. A node k/n of level l is node
      // 2k/(2n) of level l + 1: the ids of level l + 1 list the old nodes first (even k), then the
      // new ones (odd k), each by increasing k.
      const double mid = 0.5;
      const double one = 1.0;
      add_level(std::span<const double>(&mid, 1), std::span<const double>(&one, 1));
      // k of every id at the finest level, grown level by level.
      std::vector<std::uint64_t> k_of_id{0};  // at level 0 "n = 0": the midpoint, k/n = 1/2
      for (unsigned l = 1; l <= levels; ++l) {
        const std::uint64_t n = std::uint64_t{1} << l;
        std::vector<std::uint64_t> k;
        if (l == 1) {
          k = {1, 0, 2};  // 1/2 is old; 0 and 1 are new
        } else {
          for (const std::uint64_t old : k_of_id) k.push_back(2 * old);
          for (std::uint64_t odd = 1; odd < n; odd += 2) k.push_back(odd);
        }
        const std::vector<double> w_by_k = clenshaw_curtis_weights(n);
        std::vector<double> nodes, w;
        for (const std::uint64_t kk : k) {
          // sin²(π/4) is 0.5000000000000001: the centre is set exactly, as at level 0.
          nodes.push_back(2 * kk == n ? 0.5 : clenshaw_curtis_node(kk, n));
          w.push_back(w_by_k[kk]);
        }
        add_level(nodes, w);
        k_of_id = std::move(k);
      }
      break;
    }
    case nested_rule_kind::gauss_patterson: {
      // quadrule's tables on [−1, 1] in increasing x; level l has 2^(l+1) − 1 nodes, and the
      // nodes of level l − 1 are those of odd index (checked by add_level).
      std::vector<std::size_t> index_of_id;  // position in the level's table, per id
      for (unsigned l = 0; l <= levels; ++l) {
        const int order = (1 << (l + 1)) - 1;
        std::vector<double> x(static_cast<std::size_t>(order)), w(x.size());
        patterson_set(order, x.data(), w.data());
        std::vector<std::size_t> index;
        for (const std::size_t old : index_of_id) index.push_back(2 * old + 1);
        for (std::size_t i = 0; i < x.size(); i += (l == 0 ? 1 : 2)) index.push_back(i);
        std::vector<double> nodes, weights;
        for (const std::size_t i : index) {
          nodes.push_back(0.5 + 0.5 * x[i]);
          weights.push_back(0.5 * w[i]);
        }
        add_level(nodes, weights);
        index_of_id = std::move(index);
      }
      break;
    }
    case nested_rule_kind::trapezoid: {
      // Level l: the nodes k/2^l of one period, weights 2^−l (exact: powers of two).
      std::vector<double> nodes{0.0};
      const double one = 1.0;
      add_level(nodes, std::span<const double>(&one, 1));
      for (unsigned l = 1; l <= levels; ++l) {
        const std::uint64_t n = std::uint64_t{1} << l;
        for (std::uint64_t odd = 1; odd < n; odd += 2) {
          nodes.push_back(static_cast<double>(odd) / static_cast<double>(n));
        }
        const std::vector<double> w(nodes.size(), 1.0 / static_cast<double>(n));
        add_level(nodes, w);
      }
      break;
    }
  }
  // The by-node tables: node id's weights and differences in the levels birth(id) … max_level.
  const unsigned top = max_level();
  by_node_offset_.reserve(nodes_.size());
  for (std::size_t id = 0; id < nodes_.size(); ++id) {
    by_node_offset_.push_back(by_node_weights_.size());
    for (unsigned l = birth_[id]; l <= top; ++l) {
      by_node_weights_.push_back(weight(l, id));
      by_node_differences_.push_back(l == birth_[id] ? weight(l, id)
                                                     : weight(l, id) - weight(l - 1, id));
    }
  }
  // The by-birth table: the same differences, for birth b and step m the new_count(b) values
  // in id order (copied from the by-node table: the same bits).
  by_birth_offset_.resize(top + 1);
  for (unsigned b = 0; b <= top; ++b) {
    by_birth_offset_[b] = by_birth_differences_.size();
    const std::size_t first = b == 0 ? 0 : static_cast<std::size_t>(count_[b - 1]);
    const auto n = static_cast<std::size_t>(new_count(b));
    for (unsigned m = 0; m + b <= top; ++m) {
      for (std::size_t k = 0; k < n; ++k) {
        by_birth_differences_.push_back(differences_from_birth(first + k)[m]);
      }
    }
  }
}

unsigned nested_rule::degree(unsigned level) const noexcept {
  switch (kind_) {
    case nested_rule_kind::clenshaw_curtis:
      // n + 1 nodes, n = 2^l even, symmetric: degree n + 1; the midpoint rule: 1.
      return level == 0 ? 1 : (1u << level) + 1;
    case nested_rule_kind::gauss_patterson:
      // 1 node: 1; the 3-point Gauss rule: 5; each Patterson extension of m nodes adds m + 1
      // nodes and reaches degree 3·2^l − 1 [Patterson 1968].
      return level == 0 ? 1 : 3 * (1u << level) - 1;
    case nested_rule_kind::trapezoid:
      // Not exact for x on one period (the end node counts once): exact for trigonometric
      // polynomials of degree < 2^l instead.
      return 0;
  }
  return 0;
}

const nested_rule& nested_rule_table(nested_rule_kind kind) {
  static const std::array<nested_rule, 3> tables{nested_rule(nested_rule_kind::clenshaw_curtis),
                                                 nested_rule(nested_rule_kind::gauss_patterson),
                                                 nested_rule(nested_rule_kind::trapezoid)};
  return tables[static_cast<std::size_t>(kind)];
}

}  // namespace quadmc
