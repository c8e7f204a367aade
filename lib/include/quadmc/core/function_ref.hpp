// A non-owning reference to a callable: a pointer to it and a pointer to a function that calls
// it, so that a kernel compiled once in the library can call back into its caller's template code
// (C++26 has std::function_ref; C++20 and Boost 1.74 do not). Unlike std::function it never
// allocates and is two pointers, passed in registers.
//
// Use it where a call happens once per batch, never per point (docs/design.md#hot-path-contract):
// the call is indirect and not inlined. The referenced callable must outlive the function_ref.
#pragma once

#include <memory>
#include <type_traits>
#include <utility>

namespace quadmc {

template <class Signature>
class function_ref;

template <class R, class... Args>
class function_ref<R(Args...)> {
 public:
  template <class F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, function_ref> &&
           std::is_invocable_r_v<R, const F&, Args...>) explicit function_ref(const F& f) noexcept
      : object_(std::addressof(f)), call_([](const void* object, Args... args) -> R {
          return (*static_cast<const F*>(object))(std::forward<Args>(args)...);
        }) {}

  R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

 private:
  const void* object_;
  R (*call_)(const void*, Args...);
};

}  // namespace quadmc
