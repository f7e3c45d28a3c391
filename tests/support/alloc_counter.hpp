// tests/support/alloc_counter.hpp: counts heap allocations made through operator new while a scope is
// active, so that tests can check that memory grows with the work, not with the canvas.
// Test-only: tests/support/alloc_counter.cpp replaces the global (non-aligned) operator new/delete of the
// test program; counting is per thread and off unless an AllocationScope is alive on that thread.
#pragma once

#include <cstddef>

namespace casteljau::testing {

struct AllocationTotals {
    std::size_t count = 0;    // calls to operator new
    std::size_t bytes = 0;    // bytes requested in total
    std::size_t largest = 0;  // largest single request
};

class AllocationScope {
public:
    AllocationScope();
    ~AllocationScope();
    AllocationScope(const AllocationScope&) = delete;
    AllocationScope& operator=(const AllocationScope&) = delete;
    AllocationTotals totals() const;
};

}  // namespace casteljau::testing
