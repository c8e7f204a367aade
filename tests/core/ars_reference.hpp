// Random123's ARS-4x32 with 7 or 10 rounds (tests/core/ars_reference.cpp): call it only where
// __builtin_cpu_supports("aes").
#pragma once

#include <array>
#include <cstdint>

namespace quadmc::test_support {

std::array<std::uint32_t, 4> random123_ars4x32(unsigned rounds,
                                               const std::array<std::uint32_t, 4>& counter,
                                               const std::array<std::uint32_t, 4>& key);

}  // namespace quadmc::test_support
