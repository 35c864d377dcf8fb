#include "Args.h"
#include "Cli.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>
#include <iostream>

namespace lpv::cli {

namespace {

// 0.5, 10000, 1e-06: as a user would type the bound.
std::string numberText(double v) {
    std::ostringstream text;
    text << v;
    return text.str();
}

std::vector<std::string> splitCommas(const std::string& text) {
    std::vector<std::string> items;
    std::size_t start = 0;
    for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
        items.push_back(text.substr(start, comma - start));
    items.push_back(text.substr(start));
    return items;
}

} // namespace

std::string IntRange::describe() const {
    constexpr int kLowest = std::numeric_limits<int>::min(), kHighest = std::numeric_limits<int>::max();
    if (min != kLowest && max != kHighest)
        return "a whole number from " + std::to_string(min) + " to " + std::to_string(max);
    if (min != kLowest)
        return "a whole number of " + std::to_string(min) + " or more";
    if (max != kHighest)
        return "a whole number of " + std::to_string(max) + " or less";
    return "a whole number";
}

bool RealRange::contains(double v) const {
    return std::isfinite(v) && (minOpen ? v > min : v >= min) && (maxOpen ? v < max : v <= max);
}

std::string RealRange::describe() const {
    const bool low = std::isfinite(min), high = std::isfinite(max);
    if (low && high)
        return std::string("a number in ") + (minOpen ? "(" : "[") + numberText(min) + ", " + numberText(max) +
               (maxOpen ? ")" : "]");
    if (low)
        return "a finite number " + (minOpen ? "above " + numberText(min) : "of " + numberText(min) + " or more");
    if (high)
        return "a finite number " + (maxOpen ? "below " + numberText(max) : "of " + numberText(max) + " or less");
    return "a finite number";
}

std::optional<int> parseInteger(const std::string& text) {
    int v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size())
        return std::nullopt;
    return v;
}

std::optional<double> parseReal(const std::string& text) {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

namespace {

// One number option: absent, or its value parsed and in range, or rejected.
template <typename T, typename Range>
std::optional<T> readNumber(Args& args, const std::string& name, const Range& range,
                            std::optional<T> (*parse)(const std::string&), std::string* given) {
    const auto text = args.option(name);
    if (!text)
        return std::nullopt;
    if (given)
        *given = *text;
    const auto v = parse(*text);
    if (!v || !range.contains(*v)) {
        args.reject(name, *text, range.describe());
        return std::nullopt;
    }
    return v;
}

} // namespace

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

std::optional<std::string> Args::option(const std::string& name, const std::string& shortName) {
    const auto longForm = option(name);
    const auto shortForm = option(shortName);
    return shortForm ? shortForm : longForm;
}

void Args::reject(const std::string& name, const std::string& text, const std::string& expected) {
    if (badValue_.empty())
        badValue_ = name + ": '" + text + "' is not " + expected;
}

std::optional<int> Args::optionalInteger(const std::string& name, IntRange range) {
    return readNumber(*this, name, range, parseInteger, nullptr);
}

int Args::integer(const std::string& name, int fallback, IntRange range) {
    return optionalInteger(name, range).value_or(fallback);
}

std::optional<double> Args::optionalReal(const std::string& name, RealRange range, std::string* given) {
    return readNumber(*this, name, range, parseReal, given);
}

double Args::real(const std::string& name, double fallback, RealRange range) {
    return optionalReal(name, range).value_or(fallback);
}

std::optional<std::vector<int>> Args::integerList(const std::string& name, IntRange range) {
    const auto text = option(name);
    if (!text)
        return std::nullopt;
    std::vector<int> values;
    for (const std::string& item : splitCommas(*text)) {
        const auto v = parseInteger(item);
        if (!v || !range.contains(*v)) {
            reject(name, *text, "a comma-separated list, each " + range.describe());
            return std::nullopt;
        }
        values.push_back(*v);
    }
    return values;
}

std::optional<std::vector<double>> Args::realList(const std::string& name, std::size_t count, RealRange range) {
    const auto text = option(name);
    if (!text)
        return std::nullopt;
    const std::vector<std::string> items = splitCommas(*text);
    std::vector<double> values;
    for (const std::string& item : items)
        if (const auto v = parseReal(item); v && range.contains(*v))
            values.push_back(*v);
    if (values.size() != items.size() || values.size() != count) {
        reject(name, *text, std::to_string(count) + " comma-separated numbers");
        return std::nullopt;
    }
    return values;
}

std::optional<std::string> Args::choice(const std::string& name, const std::vector<std::string>& choices) {
    const auto text = option(name);
    if (!text || std::ranges::find(choices, *text) != choices.end())
        return text;
    std::string list;
    for (std::size_t i = 0; i < choices.size(); ++i)
        list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
    reject(name, *text, list);
    return std::nullopt;
}

std::optional<std::filesystem::path> Args::path(const std::string& name) {
    const auto text = option(name);
    if (!text)
        return std::nullopt;
    if (text->empty()) {
        reject(name, *text, "a path");
        return std::nullopt;
    }
    return std::filesystem::path(*text);
}

std::optional<reference::ShardSpec> Args::shard(const std::string& name) {
    const auto text = option(name);
    if (!text)
        return std::nullopt;
    const auto spec = reference::parseShard(*text);
    if (!spec) {
        reject(name, *text, "I/N with 0 <= I < N (e.g. 0/4: the first of four shards)");
        return std::nullopt;
    }
    return *spec;
}

std::optional<std::string> Args::unknownOption() const {
    for (const std::string& a : args_)
        if (a.starts_with("--") || (a.size() > 1 && a[0] == '-' && !std::isdigit(static_cast<unsigned char>(a[1]))))
            return a;
    return std::nullopt;
}

std::optional<std::string> Args::optionProblem() const {
    if (!badValue_.empty())
        return badValue_;
    if (!missingValue_.empty())
        return missingValue_ + " needs a value";
    if (auto unknown = unknownOption())
        return "unknown option '" + *unknown + "'";
    return std::nullopt;
}

std::optional<std::string> Args::error() const {
    if (auto problem = optionProblem())
        return problem;
    if (!badPositionals_.empty())
        return badPositionals_;
    if (!missingRequired_.empty())
        return missingRequired_;
    return std::nullopt;
}

void Args::require(bool given, const std::string& missing) {
    if (!given && missingRequired_.empty())
        missingRequired_ = missing;
}

std::vector<std::string> Args::expectPositionals(std::size_t count, const std::string& expected, std::size_t skip) {
    if (optionProblem())
        return {};
    if (args_.size() < skip || args_.size() - skip != count) {
        badPositionals_ = expected;
        return {};
    }
    if (!missingRequired_.empty())
        return {};
    return {args_.begin() + std::ptrdiff_t(skip), args_.end()};
}

int usageError(const std::string& message, const std::string& command) {
    std::cerr << "lpv: " << message << "\n";
    std::cerr << "Try 'lpv " << (command.empty() ? "--help" : command + " --help") << "'.\n";
    return kUsage;
}

} // namespace lpv::cli
