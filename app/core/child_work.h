// How a child of runIsolated() (core/isolated.h) and runInPool()
// (core/process_pool.h) runs its work and reports back, in one place: the
// address-space limit, the work's text (or error message) written to the
// pipe, and the exit status that says how it ended.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace rl {

constexpr int kChildOutOfMemoryStatus = 4;  // the work threw std::bad_alloc
constexpr char kChildErrorMark = '\x01';    // output that is an error message, not a result

// In a freshly forked child: limits its address space to `memoryBytes` (0:
// none; never under AddressSanitizer, which maps terabytes of shadow
// memory), runs `work`, writes what it returned to `fd` (or kChildErrorMark
// and the message of what it threw) and exits: 0, kChildOutOfMemoryStatus,
// or the status of a ChildExit (core/process_pool.h).
[[noreturn]] void finishChild(const std::function<std::string()>& work, std::size_t memoryBytes, int fd);

}  // namespace rl
