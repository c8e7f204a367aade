// libFuzzer target for the scene parser (scene/parse.hpp): any byte string must either parse into
// a scene or raise quadmc::scene_error / quadmc::invalid_argument — never crash, hang, leak, read
// out of bounds or hit undefined behaviour (the sanitizers run with it). Any other exception
// escapes LLVMFuzzerTestOneInput and libFuzzer reports it as a crash.
//
// Use tests/fuzz/run.sh to build it (clang, -fsanitize=fuzzer,address,undefined, in the sanitize
// preset's tree: tests/fuzz/CMakeLists.txt) and run it (CI: 60 s). Not a unit test: it has no
// fixed inputs beyond its seed corpus (bench/scenes/*.toml).
// Source: LLVM libFuzzer documentation, https://llvm.org/docs/LibFuzzer.html.
#include "quadmc/scene/parse.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const quadmc::scene sc = quadmc::parse_scene(text, "fuzz.toml");
    // A scene that parses honours the reference's invariants.
    if (sc.integrands.empty() || sc.methods.empty() || sc.budget.N.empty()) __builtin_trap();
  } catch (const quadmc::scene_error&) {
  } catch (const quadmc::invalid_argument&) {
  }
  return 0;
}
