#pragma once
// Storage that a hot function keeps per thread from one call to the next instead of allocating
// it anew on every call, and the rule that keeps it small. Internal.

#include <cstddef>
#include <vector>

namespace acdplan::acd::internal {

/// Above this, a thread's scratch storage is released when the call that used it ends: a thread
/// keeps no large buffer after a large input (where one allocation more costs next to nothing).
inline constexpr std::size_t kRetainedScratchBytes = std::size_t{1} << 20;

/// Releases `storage` (a std::vector, or a class with HeldBytes() and Release()) on leaving the
/// scope if it then holds more than kRetainedScratchBytes.
template <typename Storage>
class ScratchScope {
 public:
  explicit ScratchScope(Storage& storage) : storage_(storage) {}
  ScratchScope(const ScratchScope&) = delete;
  ScratchScope& operator=(const ScratchScope&) = delete;
  ~ScratchScope() {
    if (HeldBytes(storage_) > kRetainedScratchBytes) Release(storage_);
  }

 private:
  template <typename T>
  static std::size_t HeldBytes(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
  }
  template <typename S>
  static std::size_t HeldBytes(const S& s) {
    return s.HeldBytes();
  }
  template <typename T>
  static void Release(std::vector<T>& v) {
    std::vector<T>().swap(v);
  }
  template <typename S>
  static void Release(S& s) {
    s.Release();
  }

  Storage& storage_;
};

}  // namespace acdplan::acd::internal
