// The generating vector of rank1_lattice_points.hpp, read once from Debian's QuantLib
// (libquantlib0-dev): the embedded lattice rules of [Cools, Kuo & Nuyens 2006].
#include "quadmc/sampling/rank1_lattice_points.hpp"

#include <ql/math/randomnumbers/latticerules.hpp>

#include <vector>

namespace quadmc {

std::span<const std::uint32_t> lattice_generating_vector() {
  static const std::vector<std::uint32_t> z = [] {
    std::vector<QuantLib::Real> rule;
    // getRule checks only that N lies in its range (2^10 … 2^20); the vector is the same for
    // every N of an embedded sequence.
    QuantLib::LatticeRule::getRule(QuantLib::LatticeRule::D, rule, 1024);
    require(rule.size() >= max_lattice_dimension, "QuantLib lattice rule length", rule.size(),
            "at least 3600 components");
    std::vector<std::uint32_t> out(max_lattice_dimension);
    for (std::size_t j = 0; j < out.size(); ++j) out[j] = static_cast<std::uint32_t>(rule[j]);
    return out;
  }();
  return z;
}

}  // namespace quadmc
