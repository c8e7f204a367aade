// Run-time choice of the kernels' instruction set (core/simd_level.hpp says what it affects).
#include "quadmc/core/simd_level.hpp"

#include "quadmc/core/errors.hpp"

#include <array>
#include <atomic>
#include <cstdlib>
#include <mutex>
#include <string>

namespace quadmc {
namespace {

constexpr std::array<std::string_view, 4> names = {"scalar", "sse2", "avx2", "avx512"};

// The vector levels need x86-64 and glibc's libmvec (the vector exp/cos); elsewhere only scalar.
#if defined(__x86_64__) && defined(QUADMC_HAVE_LIBMVEC)
constexpr bool vector_build = true;
#else
constexpr bool vector_build = false;
#endif

bool supported(simd_level level) noexcept {
  return level <= detected_simd_level();
}

// -1 = not chosen yet. An atomic so that concurrent first uses agree, not for mid-run changes.
std::atomic<int> chosen{-1};
std::once_flag environment_read;

}  // namespace

std::string_view to_string(simd_level level) noexcept {
  return names[static_cast<std::size_t>(level)];
}

simd_level parse_simd_level(std::string_view text, std::string_view parameter) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (text == names[i]) return static_cast<simd_level>(i);
  }
  throw invalid_argument(parameter, std::string(text), "one of scalar, sse2, avx2, avx512");
}

simd_level detected_simd_level() noexcept {
  if constexpr (!vector_build) {
    return simd_level::scalar;
  } else {
#if defined(__x86_64__)
    // AVX-512: libmvec's 8-lane variants need AVX512F; the Philox kernel uses only AVX512F too.
    if (__builtin_cpu_supports("avx512f")) return simd_level::avx512;
    // libmvec's 4-lane variants are the AVX2 ABI ('d' in the x86_64 vector function ABI).
    if (__builtin_cpu_supports("avx2")) return simd_level::avx2;
#endif
    return simd_level::sse2;  // part of every x86-64
  }
}

std::vector<simd_level> available_simd_levels() {
  std::vector<simd_level> levels;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (supported(static_cast<simd_level>(i))) levels.push_back(static_cast<simd_level>(i));
  }
  return levels;
}

simd_level active_simd_level() {
  int level = chosen.load(std::memory_order_acquire);
  if (level >= 0) [[likely]]
    return static_cast<simd_level>(level);
  std::call_once(environment_read, [] {
    simd_level wanted = detected_simd_level();
    if (const char* text = std::getenv("QUADMC_SIMD"); text != nullptr && *text != '\0') {
      wanted = parse_simd_level(text, "QUADMC_SIMD");
      require(supported(wanted), "QUADMC_SIMD", std::string(text),
              fmt::format("a level this CPU and build support (at most {})",
                          to_string(detected_simd_level())));
    }
    int expected = -1;
    chosen.compare_exchange_strong(expected, static_cast<int>(wanted));
  });
  return static_cast<simd_level>(chosen.load(std::memory_order_acquire));
}

void set_simd_level(simd_level level) {
  require(supported(level), "simd level", std::string(to_string(level)),
          fmt::format("a level this CPU and build support (at most {})",
                      to_string(detected_simd_level())));
  chosen.store(static_cast<int>(level), std::memory_order_release);
}

}  // namespace quadmc
