#pragma once
// A small command-line parser for snaxels-cli: --name VALUE, --name=VALUE,
// flags, repeatable options and positionals, with generated help text.

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace snaxels::cli {

/// A usage mistake; main prints it with a hint to --help and exits 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct OptionSpec {
    std::string name;     ///< without the leading dashes
    std::string value;    ///< value placeholder for help; empty for a flag
    std::string help;
    bool repeatable = false;
    char short_name = 0; ///< also accepted as -X
};

class Args {
  public:
    Args(std::string command, std::string synopsis, std::string description,
         std::vector<OptionSpec> options, std::vector<std::string> positional_names);

    /// Parses argv after the command word. Returns false if --help was given.
    bool parse(const std::vector<std::string>& argv);

    std::string help() const;

    bool flag(const std::string& name) const { return values_.count(name) > 0; }
    std::optional<std::string> value(const std::string& name) const;
    std::vector<std::string> values(const std::string& name) const;
    const std::vector<std::string>& positional() const { return positional_; }

  private:
    const OptionSpec* find(const std::string& name) const;

    std::string command_, synopsis_, description_;
    std::vector<OptionSpec> options_;
    std::vector<std::string> positional_names_;
    std::map<std::string, std::vector<std::string>> values_;
    std::vector<std::string> positional_;
};

} // namespace snaxels::cli
