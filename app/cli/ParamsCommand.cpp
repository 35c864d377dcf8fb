#include "Cli.h"

#include "lpv/scene/ParameterRegistry.h"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace lpv::cli {

void printParamsHelp() {
    std::cout << R"(Usage: lpv params [--json]

Lists every parameter of the registry: key, type, default, range or allowed
values, unit, group, the passes a change invalidates, and a description.
Any of them can be set for a run with `lpv render --set key=value` and is
saved in a project's "parameters" object.

  --json    Print the registry as JSON instead of a table
)";
}

int runParams(Args args) {
    const bool json = args.flag("--json");
    if (auto e = args.error())
        return usageError(*e, "params");
    if (!args.positionals().empty())
        return usageError("unexpected argument '" + args.positionals().front() + "'", "params");
    const auto& registry = scene::ParameterRegistry::instance();
    if (json) {
        std::cout << registry.toJson() << "\n";
        return kOk;
    }
    std::string group;
    for (const scene::ParameterInfo& p : registry.all()) {
        std::ostringstream range;
        if (p.type == scene::ParameterType::Int || p.type == scene::ParameterType::Float) {
            for (const std::string& word : p.enumValues) // a Float's words: lpv.cellSize's "auto"
                range << word << "|";
            range << "[" << p.minValue << ", " << p.maxValue << "]";
        }
        else if (p.type == scene::ParameterType::Enum)
            for (std::size_t i = 0; i < p.enumValues.size(); ++i)
                range << (i ? "|" : "") << p.enumValues[i];
        else
            range << "true|false";
        std::string passes;
        for (const std::string& n : scene::passNames(p.invalidates))
            passes += (passes.empty() ? "" : ",") + n;
        std::printf("%-30s %-6s %-14s %-52s %-7s %s\n", p.key.c_str(), scene::toString(p.type),
                    scene::formatValue(p.defaultValue).c_str(), range.str().c_str(), p.unit.c_str(),
                    p.group.c_str());
        std::printf("    %s\n    invalidates: %s\n", p.description.c_str(), passes.c_str());
    }
    std::printf("%zu parameters\n", registry.all().size());
    return kOk;
}

} // namespace lpv::cli
