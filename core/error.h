#pragma once
/// Errors raised by the core library, all derived from snaxels::Error (one
/// catch takes them all). Every message is one line meant for a user: it
/// names the file or input and what is wrong with it.

#include <stdexcept>
#include <string>

namespace snaxels {

class Error : public std::runtime_error {
  public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// A fault of the program rather than of its input: a broken invariant
/// (under --check), or a fault injected for a test (fault_injected). The
/// command line exits 3 on it, the application says so in a message box.
class InternalError : public Error {
  public:
    explicit InternalError(const std::string& message) : Error(message) {}
};

/// The user stopped long work (an export, a search) before it ended: not a
/// failure, so callers say so, or nothing, rather than report an error.
class Cancelled : public Error {
  public:
    explicit Cancelled(const std::string& message) : Error(message) {}
};

/// Test seam: true when the environment variable SNAXELS_FAULT names
/// @p site with this @p count ("tracker-step:3" faults the fourth tracked
/// frame of every contour kind). Unset in normal use.
bool fault_injected(const char* site, long count);

} // namespace snaxels
