// tests/support/alloc_counter.cpp: see alloc_counter.hpp.
#include "alloc_counter.hpp"

#include <cstdlib>
#include <new>

namespace casteljau::testing {
namespace {
thread_local AllocationTotals* g_active = nullptr;  // the innermost live scope's totals
thread_local AllocationTotals g_totals;
thread_local int g_depth = 0;
}  // namespace

AllocationScope::AllocationScope() {
    if (g_depth++ == 0) g_totals = {};
    g_active = &g_totals;
}
AllocationScope::~AllocationScope() {
    if (--g_depth == 0) g_active = nullptr;
}
AllocationTotals AllocationScope::totals() const { return g_totals; }

namespace {
void* counted_alloc(std::size_t n) {
    if (AllocationTotals* t = g_active) {
        ++t->count;
        t->bytes += n;
        if (n > t->largest) t->largest = n;
    }
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
}  // namespace

}  // namespace casteljau::testing

void* operator new(std::size_t n) { return casteljau::testing::counted_alloc(n); }
void* operator new[](std::size_t n) { return casteljau::testing::counted_alloc(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return casteljau::testing::counted_alloc(n);
    } catch (...) { return nullptr; }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return casteljau::testing::counted_alloc(n);
    } catch (...) { return nullptr; }
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
