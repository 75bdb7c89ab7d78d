// Hands the heap's freed pages back to the system between the steps of a build, so that the
// next step's allocations do not add to what earlier steps freed: glibc keeps freed memory of
// each malloc arena resident (and a worker thread allocates from its own arena, where the
// calling thread's frees cannot be reused). Elsewhere it does nothing. Host code.
#pragma once

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace amrdm
{

/// Returns the freed heap pages of every malloc arena to the system (glibc's malloc_trim).
inline void releaseFreedMemory()
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

} // namespace amrdm
