// Included first in every source of the scene-parser fuzzer (tests/fuzz/CMakeLists.txt).
//
// toml++ is compiled in header-only mode, not linked as Debian's shared library: that way its
// parser is instrumented too, so the fuzzer gets coverage feedback from inside the TOML grammar
// and the sanitizers watch it. Its internal assertions are compiled out, as in Debian's
// libtomlplusplus.so that the library links: toml++ 3.3.0 asserts in parse_key() on input such as
// "[=]" although the very next branch reports that as a parse error (which is what the shipped
// library does), so leaving them on would only re-find that one false alarm.
#pragma once

#define TOML_HEADER_ONLY 1
#define TOML_ASSERT(expr) static_cast<void>(0)
