// A 3-vector of doubles for the rendering integrands (irradiance.hpp) and the estimators that
// sample them.
//
// Use it for the few vector operations a direct-lighting integrand needs (Pharr, Jakob &
// Humphreys, "Physically Based Rendering", 4th ed., §3.3 has the same set). Not a linear-algebra
// library: no matrices, no SIMD layout; a batch kernel keeps its vec3s in registers.
// Everything is constexpr except length/normalize (std::sqrt is not constexpr in C++20).
#pragma once

#include <cmath>

namespace quadmc {

struct vec3 {
  double x, y, z;
};

constexpr vec3 operator+(vec3 a, vec3 b) noexcept {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
constexpr vec3 operator-(vec3 a, vec3 b) noexcept {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
constexpr vec3 operator-(vec3 a) noexcept {
  return {-a.x, -a.y, -a.z};
}
constexpr vec3 operator*(vec3 a, double k) noexcept {
  return {a.x * k, a.y * k, a.z * k};
}
constexpr vec3 operator*(double k, vec3 a) noexcept {
  return {a.x * k, a.y * k, a.z * k};
}
constexpr vec3 operator/(vec3 a, double k) noexcept {
  return {a.x / k, a.y / k, a.z / k};
}
constexpr bool operator==(vec3 a, vec3 b) noexcept {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

constexpr double dot(vec3 a, vec3 b) noexcept {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr vec3 cross(vec3 a, vec3 b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double length_squared(vec3 a) noexcept {
  return dot(a, a);
}
inline double length(vec3 a) noexcept {
  return std::sqrt(dot(a, a));
}
// a/|a|; the zero vector gives NaNs, so callers validate lengths first (irradiance.hpp does).
inline vec3 normalize(vec3 a) noexcept {
  return a / length(a);
}

}  // namespace quadmc
