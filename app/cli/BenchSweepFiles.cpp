// writeSweepFiles (BenchReport.h) in a file of its own: it writes the sweep's
// plots through lpv_bench's SweepOutput (OpenImageIO), which the GPU bench
// program (app/glbench, issue #45) links without; it shares the rest of
// BenchReport.cpp.
#include "BenchReport.h"

#include "lpv/bench/SweepOutput.h"

#include <cstdio>
#include <iostream>

namespace lpv::cli {

bool writeSweepFiles(const std::filesystem::path& outDir, const std::vector<SweepRun>& runs, int width, int height,
                     const std::string& command, const std::string& machine, const reference::ReferenceImage& ref,
                     const std::string& note, const bench::SweepTimingInfo& timing,
                     const scene::ParameterSet& display) {
    auto written = bench::writeSweepOutputs(outDir, runs, width, height, command, machine, ref, note, timing, display);
    if (!written) {
        std::cerr << "lpv: " << written.error().describe() << "\n";
        return false;
    }
    for (const auto& file : *written)
        std::printf("wrote %s\n", file.string().c_str());
    return true;
}

} // namespace lpv::cli
