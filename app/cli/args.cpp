#include "app/cli/args.h"

#include <sstream>

namespace snaxels::cli {

Args::Args(std::string command, std::string synopsis, std::string description,
           std::vector<OptionSpec> options, std::vector<std::string> positional_names)
    : command_(std::move(command)), synopsis_(std::move(synopsis)),
      description_(std::move(description)), options_(std::move(options)),
      positional_names_(std::move(positional_names)) {}

const OptionSpec* Args::find(const std::string& name) const {
    for (const auto& o : options_)
        if (o.name == name) return &o;
    return nullptr;
}

bool Args::parse(const std::vector<std::string>& argv) {
    for (std::size_t i = 0; i < argv.size(); ++i) {
        std::string a = argv[i];
        if (a == "--help" || a == "-h") return false;
        if (a.size() == 2 && a[0] == '-' && a[1] != '-')
            for (const auto& o : options_)
                if (o.short_name == a[1]) a = "--" + o.name;
        if (a.size() > 2 && a.compare(0, 2, "--") == 0) {
            std::string name = a.substr(2), inline_value;
            bool has_inline = false;
            if (const auto eq = name.find('='); eq != std::string::npos) {
                inline_value = name.substr(eq + 1);
                name = name.substr(0, eq);
                has_inline = true;
            }
            const OptionSpec* spec = find(name);
            if (!spec) throw UsageError("unknown option --" + name + " for '" + command_ + "'");
            if (!spec->repeatable && values_.count(name))
                throw UsageError("--" + name + " is given more than once");
            if (spec->value.empty()) {
                if (has_inline) throw UsageError("--" + name + " takes no value");
                values_[name].push_back("");
                continue;
            }
            if (!has_inline) {
                if (i + 1 >= argv.size())
                    throw UsageError("--" + name + " needs a value (" + spec->value + ")");
                inline_value = argv[++i];
            }
            values_[name].push_back(inline_value);
            continue;
        }
        positional_.push_back(a);
    }
    if (positional_.size() < positional_names_.size())
        throw UsageError("'" + command_ + "' needs " + positional_names_[positional_.size()]);
    if (positional_.size() > positional_names_.size())
        throw UsageError("unexpected argument '" + positional_[positional_names_.size()] + "'");
    return true;
}

std::optional<std::string> Args::value(const std::string& name) const {
    const auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    return it->second.back();
}

std::vector<std::string> Args::values(const std::string& name) const {
    const auto it = values_.find(name);
    return it == values_.end() ? std::vector<std::string>{} : it->second;
}

std::string Args::help() const {
    std::ostringstream out;
    out << "usage: snaxels-cli " << synopsis_ << "\n\n" << description_ << "\n";
    if (!options_.empty()) {
        out << "\noptions:\n";
        for (const auto& o : options_) {
            std::string head = std::string("  ") + (o.short_name ? std::string("-") + o.short_name + ", " : "") +
                               "--" + o.name + (o.value.empty() ? "" : " " + o.value);
            if (head.size() < 28) head.resize(28, ' ');
            else head += "\n" + std::string(28, ' ');
            out << head << o.help << (o.repeatable ? " (repeatable)" : "") << "\n";
        }
        out << "  --help                    show this help\n";
    }
    return out.str();
}

} // namespace snaxels::cli
