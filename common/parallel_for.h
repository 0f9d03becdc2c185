// Work split over threads in chunks taken in turn from a shared counter: items are independent,
// so results do not depend on the thread count or on which thread ran which chunk (each item's
// random numbers are a function of the item, docs/architecture.md "Randomness").
#pragma once

#include <cstddef>
#include <functional>

namespace gib {

// Calls body(begin, end) over [0, count) in chunks of `chunk` items on `threads` threads (0: one
// per hardware thread); returns when all are done. An exception from a body is rethrown here
// once every thread has stopped.
void parallelFor(std::size_t count, int threads, std::size_t chunk,
                 const std::function<void(std::size_t begin, std::size_t end)>& body);

// What `threads` means: itself if positive, else the hardware's thread count (at least 1).
int resolveThreadCount(int threads);

}  // namespace gib
