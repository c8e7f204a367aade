// The peers as methods a scene can name (their names are methods/registry.hpp's peers::known, the
// one list of them): the libraries themselves behind quadmc's method interface, so that they run
// in the same cells, with the same integrands, timing and statistics as the suite's own methods.
//
// Use it through the quadmc_with_peers command (bench/peers/CMakeLists.txt), which links
// peer_scene_methods.cpp: its static initialiser adds these descriptors to the registry
// (methods/registry.hpp, add_methods) before main. Not part of the library or of the `quadmc`
// command: GSL and cubature are GPL, and the library must build and run without them (a scene
// naming a peer there fails at plan time saying how to get it). For the stand-alone peers
// benchmark (throughput, memory) see quadmc_peers.cpp.
#pragma once

#include "quadmc/methods/method.hpp"

#include <span>

namespace quadmc::peers {

// The descriptors, in listing order (also registered by the static initialiser).
std::span<const method_descriptor> peer_scene_methods() noexcept;

}  // namespace quadmc::peers
