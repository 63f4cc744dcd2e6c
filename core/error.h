#pragma once
/// Errors raised by the core library. Every message is one line meant for a
/// user: it names the file or input and what is wrong with it.

#include <stdexcept>
#include <string>

namespace snaxels {

class Error : public std::runtime_error {
  public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

} // namespace snaxels
