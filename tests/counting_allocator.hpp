//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Replaces the global operator new and counts every call in `allocations`
// (the no-allocation tests: include it in exactly one source of a binary).
#ifndef SPINSLIDE_TESTS_COUNTING_ALLOCATOR_HPP
#define SPINSLIDE_TESTS_COUNTING_ALLOCATOR_HPP

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> allocations{0};

// The allocations of one call of f() after a first call (which may
// initialise something lazily): the no-allocation tests' measure.
template <class F>
long allocations_of(F&& f, double& result) {
  f();
  const long before = allocations.load();
  result = static_cast<double>(f());
  return allocations.load() - before;
}
}  // namespace

// GCC cannot see that these replace the global pair, and warns that free()
// releases memory from operator new; here that is exactly the intent.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

void* operator new(std::size_t n) {
  ++allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

#endif  // SPINSLIDE_TESTS_COUNTING_ALLOCATOR_HPP
