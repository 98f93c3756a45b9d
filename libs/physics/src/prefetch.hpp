// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

namespace e2d::physics::detail {

// Asks for every cache line of *p. GCC drops prefetches without a word in two cases, checked
// in the disassembly: a write prefetch on plain x86-64 (PREFETCHW needs -mprfchw), so this is
// a read prefetch even where the caller will write; and a call to a function that does
// nothing but prefetch, which it finds free of side effects and deletes, so this is always
// inlined and must not be wrapped in another function or lambda.
// Arrays smaller than this stay in the cache from one step to the next (measured on the narrow
// phase's shapes and bodies): prefetching them only costs instructions.
inline constexpr std::size_t kPrefetchBytes = std::size_t{1} << 20;

template <class T>
[[gnu::always_inline]] inline void prefetchObject(const T* p) {
    const auto* bytes = reinterpret_cast<const char*>(p);
    for (std::size_t offset = 0; offset < sizeof(T); offset += 64) {
        __builtin_prefetch(bytes + offset);
    }
    __builtin_prefetch(bytes + sizeof(T) - 1);
}

// Asks for the cache lines of the first kBytes bytes of *p (same rules as prefetchObject()).
template <std::size_t kBytes, class T>
[[gnu::always_inline]] inline void prefetchFirst(const T* p) {
    static_assert(kBytes <= sizeof(T));
    const auto* bytes = reinterpret_cast<const char*>(p);
    for (std::size_t offset = 0; offset < kBytes; offset += 64) {
        __builtin_prefetch(bytes + offset);
    }
    __builtin_prefetch(bytes + kBytes - 1);
}

} // namespace e2d::physics::detail
