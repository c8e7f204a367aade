// Random123's own ARS-4x32 (ars.h), the reference of tests/core/ars_blocks_test.cpp. ars.h exists
// only where the compiler may emit AES-NI, so this file alone is built with -maes
// (tests/CMakeLists.txt), and the tests call it only on a CPU that has AES-NI.
#include "ars_reference.hpp"

#include <Random123/ars.h>

namespace quadmc::test_support {

std::array<std::uint32_t, 4> random123_ars4x32(unsigned rounds,
                                               const std::array<std::uint32_t, 4>& counter,
                                               const std::array<std::uint32_t, 4>& key) {
  const r123::ARS4x32::ctr_type c = {{counter[0], counter[1], counter[2], counter[3]}};
  const r123::ARS4x32::key_type k = {{key[0], key[1], key[2], key[3]}};
  const r123::ARS4x32::ctr_type r =
      rounds == 10 ? r123::ARS4x32_R<10>{}(c, k) : r123::ARS4x32_R<7>{}(c, k);
  return {r.v[0], r.v[1], r.v[2], r.v[3]};
}

}  // namespace quadmc::test_support
