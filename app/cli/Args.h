#pragma once
// The command line of one `lpv` command: options read by name, typed and
// range-checked here, so that every command says a bad value the same way:
//   lpv: --width: 'abc' is not a whole number of 1 or more
// A getter never stops the command. It returns the fallback (or nullopt) and
// records the first problem; the command reads all its options, then asks
// error() once, as it asks for unknown options.
#include "lpv/reference/Shards.h"

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace lpv::cli {

// The whole numbers an option takes, both ends included.
struct IntRange {
    int min = std::numeric_limits<int>::min();
    int max = std::numeric_limits<int>::max();

    bool contains(int v) const { return v >= min && v <= max; }
    std::string describe() const; // "a whole number from 1 to 64", "a whole number of 0 or more"
};

// The finite real numbers an option takes; an open end excludes its bound.
struct RealRange {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minOpen = false;
    bool maxOpen = false;

    static RealRange above(double v) { return {v, std::numeric_limits<double>::infinity(), true, false}; }
    static RealRange atLeast(double v) { return {v, std::numeric_limits<double>::infinity(), false, false}; }
    bool contains(double v) const;
    std::string describe() const; // "a finite number above 0", "a number in (0, 1]"
};

// A whole number, or a finite real number, that is the whole of `text`; nullopt otherwise.
std::optional<int> parseInteger(const std::string& text);
std::optional<double> parseReal(const std::string& text);

// Reads "--name value", "--name=value", flags and positionals in order.
class Args {
  public:
    explicit Args(std::vector<std::string> args) : args_(std::move(args)) {}

    bool flag(const std::string& name);                         // removes it if present
    std::optional<std::string> option(const std::string& name); // last occurrence, removed
    // An option with a short form ("--output", "-o"); the short form wins when both are given.
    std::optional<std::string> option(const std::string& name, const std::string& shortName);
    std::vector<std::string> options(const std::string& name); // every occurrence, removed

    // Typed options (last occurrence, removed): `fallback` or nullopt when
    // absent, and when the value is bad (the problem then kept for error()).
    // `given` receives the text as typed, for a command that echoes it.
    int integer(const std::string& name, int fallback, IntRange range = {});
    std::optional<int> optionalInteger(const std::string& name, IntRange range = {});
    double real(const std::string& name, double fallback, RealRange range = {});
    std::optional<double> optionalReal(const std::string& name, RealRange range = {},
                                       std::string* given = nullptr);
    // Comma-separated: "--tiles 32,64,128"; every item in the range, at least one.
    std::optional<std::vector<int>> integerList(const std::string& name, IntRange range = {});
    std::optional<std::vector<double>> realList(const std::string& name, std::size_t count,
                                                RealRange range = {});
    // One of `choices`; the problem lists them.
    std::optional<std::string> choice(const std::string& name, const std::vector<std::string>& choices);
    std::optional<std::filesystem::path> path(const std::string& name);
    // "--shard I/N" (reference::parseShard): the I-th of N pieces, counted from 0.
    std::optional<reference::ShardSpec> shard(const std::string& name);

    // What is left once options are taken; anything starting with "--" is an unknown option.
    std::vector<std::string> positionals() const { return args_; }
    // An option the command cannot run without: unless `given`, `missing`
    // is a problem, said after those of the options and the positionals.
    void require(bool given, const std::string& missing);
    // Read after every option: the positionals after `skip` leading words (a
    // subcommand such as "lpv"), when the command line is sound and they are
    // exactly `count`; else empty, and error() says why (`expected` for a
    // wrong count, then the first required option missing).
    std::vector<std::string> expectPositionals(std::size_t count, const std::string& expected,
                                               std::size_t skip = 0);
    std::optional<std::string> unknownOption() const;
    // Set when an option was given without its value.
    const std::string& missingValue() const { return missingValue_; }
    // The first bad value a typed getter met ("--width: 'abc' is not ..."),
    // else an option without its value, else an unknown option; nullopt when
    // the command line is sound. Call it after reading every option.
    std::optional<std::string> error() const;

    // A problem the command found in a value itself (a relation between
    // options, say), said in the same style; the first one is kept.
    void reject(const std::string& name, const std::string& text, const std::string& expected);

  private:
    std::vector<std::string> args_;
    std::string missingValue_;
    std::string badValue_;
    std::string badPositionals_;
    std::string missingRequired_;

    std::optional<std::string> optionProblem() const; // a bad, valueless or unknown option
};

} // namespace lpv::cli
