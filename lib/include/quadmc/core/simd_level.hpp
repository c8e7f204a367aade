// Which instruction set the batched kernels (Philox blocks, vector exp/cos) run on: chosen at run
// time, never at build time, so one binary built for baseline x86-64 uses AVX2 or AVX-512 where
// the CPU has them (docs/design.md#hot-path-contract: run-time dispatch, never -march=native).
//
// What depends on the level:
//  - Philox uniforms (core/rng.hpp): nothing but speed. Every level computes the same
//    Philox4x32-10 function, bit for bit (tests/core/philox_blocks_test.cpp).
//  - exp, cos (core/vector_math.hpp): the last bits. The vector levels call glibc's libmvec,
//    whose results may differ from scalar glibc by a few ulp (tests/core/vector_math_test.cpp
//    states and checks the bound). Results are bitwise identical for any thread count at one
//    level; to get the same bits on two machines, run both at the same level (QUADMC_SIMD=sse2
//    runs on every x86-64, QUADMC_SIMD=scalar everywhere).
//
// The level is process-wide: detected from the CPU on first use, or taken from the environment
// variable QUADMC_SIMD (scalar | sse2 | avx2 | avx512), or set by set_simd_level() before a run.
#pragma once

#include <string_view>
#include <vector>

namespace quadmc {

enum class simd_level { scalar, sse2, avx2, avx512 };

std::string_view to_string(simd_level level) noexcept;

// Parses "scalar", "sse2", "avx2", "avx512"; throws invalid_argument naming `parameter` otherwise.
simd_level parse_simd_level(std::string_view text, std::string_view parameter = "simd level");

// The best level this CPU and this build support (scalar on a non-x86-64 or non-glibc build).
simd_level detected_simd_level() noexcept;

// Every level this CPU and build support, scalar first: what set_simd_level() accepts (the
// tests run each kernel at each of them).
std::vector<simd_level> available_simd_levels();

// The level the kernels use now: QUADMC_SIMD if set (read once), else detected_simd_level().
// An invalid or unsupported QUADMC_SIMD throws invalid_argument on first use.
simd_level active_simd_level();

// Makes the kernels use `level` from now on; throws invalid_argument if the CPU lacks it. Not
// meant to change while a computation runs on other threads (each batch reads it once).
void set_simd_level(simd_level level);

}  // namespace quadmc
