// The heap canopy measures with (run/heap_settings.hpp): memory a driver frees stays in the
// process, so reallocating it every frame costs no page faults inside a timed pass.
#include "run/heap_settings.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#if defined(__SANITIZE_ADDRESS__)
#define CANOPY_OWN_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CANOPY_OWN_MALLOC 0
#endif
#endif
#ifndef CANOPY_OWN_MALLOC
#define CANOPY_OWN_MALLOC 1
#endif

TEST_CASE("heap settings: defaults until held, then recorded, applied once") {
    CHECK(canopy::heap_settings() == "allocator defaults");
    const std::string held = canopy::hold_heap_still();
    CHECK(canopy::heap_settings() == held);
    CHECK(canopy::hold_heap_still() == held);
#if defined(__GLIBC__) && CANOPY_OWN_MALLOC
    CHECK(held == "glibc trim_threshold=1073741824 mmap_threshold=33554432 top_pad=67108864");
#else
    // A sanitizer's allocator replaces glibc's and refuses mallopt: the record says so.
    CHECK(held.rfind("allocator defaults", 0) == 0);
#endif
}

#if defined(__GLIBC__) && CANOPY_OWN_MALLOC
TEST_CASE("heap settings: a freed 8 MiB block stays in the heap instead of going back to the kernel") {
    canopy::hold_heap_still();
    const size_t mmapped = mallinfo2().hblkhd;
    constexpr size_t kBytes = size_t(8) << 20;  // glibc's defaults would mmap it and unmap it on free
    void* block = std::malloc(kBytes);
    REQUIRE(block);
    std::memset(block, 1, kBytes);
    const size_t held = mallinfo2().arena;
    CHECK(mallinfo2().hblkhd == mmapped);  // from the heap, not an mmap of its own
    CHECK(held >= kBytes);
    std::free(block);
    CHECK(mallinfo2().arena == held);  // not trimmed
}
#endif
