#include "Cli.h"

#include <algorithm>
#include <iostream>

namespace lpv::cli {

bool Args::flag(const std::string& name) {
    auto it = std::find(args_.begin(), args_.end(), name);
    if (it == args_.end())
        return false;
    args_.erase(it);
    return true;
}

std::vector<std::string> Args::options(const std::string& name) {
    std::vector<std::string> values;
    for (std::size_t i = 0; i < args_.size();) {
        if (args_[i] == name) {
            if (i + 1 >= args_.size()) {
                missingValue_ = name;
                args_.erase(args_.begin() + std::ptrdiff_t(i));
                continue;
            }
            values.push_back(args_[i + 1]);
            args_.erase(args_.begin() + std::ptrdiff_t(i), args_.begin() + std::ptrdiff_t(i + 2));
        } else if (args_[i].starts_with(name + "=")) {
            values.push_back(args_[i].substr(name.size() + 1));
            args_.erase(args_.begin() + std::ptrdiff_t(i));
        } else {
            ++i;
        }
    }
    return values;
}

std::optional<std::string> Args::option(const std::string& name) {
    auto all = options(name);
    if (all.empty())
        return std::nullopt;
    return all.back();
}

std::optional<std::string> Args::unknownOption() const {
    for (const std::string& a : args_)
        if (a.starts_with("--") || (a.size() > 1 && a[0] == '-' && !std::isdigit(static_cast<unsigned char>(a[1]))))
            return a;
    return std::nullopt;
}

int usageError(const std::string& message, const std::string& command) {
    std::cerr << "lpv: " << message << "\n";
    std::cerr << "Try 'lpv " << (command.empty() ? "--help" : command + " --help") << "'.\n";
    return kUsage;
}

} // namespace lpv::cli
