// Test support: one computation on every SIMD target, for kernels that promise the same bytes
// whatever the target (Highway's runtime dispatch, src/core/simd_dispatch.hpp).
#pragma once

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/simd_dispatch.hpp"

namespace casteljau::test {

// Runs `render` (returning bytes) once per target the CPU runs, best first, and CHECKs that every
// target gives the first one's bytes; returns those. Differences are counted, not printed: the
// bytes may be megabytes. The choice of target is restored to the CPU's best afterwards.
template <class Render>
std::vector<std::uint8_t> same_bytes_on_every_target(Render&& render) {
    struct Restore {
        ~Restore() { simd::restrict_targets(0); }
    } restore;
    const std::vector<std::int64_t> targets = simd::available_targets();
    REQUIRE(!targets.empty());
    std::vector<std::uint8_t> first;
    for (std::int64_t t : targets) {
        simd::restrict_targets(t);
        INFO("SIMD target " << simd::target_name(t));
        const std::vector<std::uint8_t> bytes = render();
        if (t == targets.front()) {
            first = bytes;
            continue;
        }
        std::size_t differing = bytes.size() == first.size() ? 0 : 1;
        for (std::size_t k = 0; k < bytes.size() && k < first.size(); ++k) differing += bytes[k] != first[k];
        CHECK(differing == 0);
    }
    return first;
}

}  // namespace casteljau::test
