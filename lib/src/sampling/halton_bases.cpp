// The prime bases of halton_points.hpp: the first 10 000 primes by a sieve of Eratosthenes, run
// once (the 10 000th prime is 104 729).
#include "quadmc/sampling/halton_points.hpp"

#include <vector>

namespace quadmc {

std::span<const std::uint32_t> halton_bases() {
  static const std::vector<std::uint32_t> primes = [] {
    constexpr std::uint32_t limit = 104730;  // primes below it: exactly 10 000
    std::vector<bool> composite(limit, false);
    std::vector<std::uint32_t> out;
    for (std::uint32_t p = 2; p < limit; ++p) {
      if (composite[p]) continue;
      out.push_back(p);
      for (std::uint64_t q = std::uint64_t{p} * p; q < limit; q += p) composite[q] = true;
    }
    require(out.size() == max_halton_dimension, "Halton bases", out.size(),
            "the first 10000 primes");
    return out;
  }();
  return primes;
}

}  // namespace quadmc
