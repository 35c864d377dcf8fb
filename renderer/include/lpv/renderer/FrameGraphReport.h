#pragma once
// What the last frame's graph did, for `lpv render --graph`, the editor and
// tests: every declared pass in execution order, what it read and wrote,
// and whether it ran, was reused or was culled, with the reason.
#include <string>
#include <vector>

namespace lpv::renderer {

enum class PassStatus { Ran, Reused, Culled };
const char* toString(PassStatus status);

struct GraphResourceUse {
    std::string name;        // a resource's name, e.g. rsm.flux
    std::string description; // "2D array RGBA16F 512x512x4"
};

struct GraphPassReport {
    std::string name; // the pass's one name (timer row, registry flag, --dump)
    PassStatus status = PassStatus::Ran;
    std::string reason;
    std::vector<std::string> reads;
    std::vector<GraphResourceUse> writes;
};

struct FrameGraphReport {
    std::vector<GraphPassReport> passes; // execution order, then the culled passes
    const GraphPassReport* find(const std::string& pass) const;
};

// The report as an indented text listing.
std::string formatGraph(const FrameGraphReport& report);

// The report as docs/renderer.md's pass table: one row per pass (execution
// order, then the culled ones) with the resources it declared reading and
// writing, from the passes' own declarations (a test keeps the doc equal).
std::string formatGraphMarkdown(const FrameGraphReport& report);

// Every pass and output name ForwardRenderer's graph can declare (for
// `--dump` to check before rendering; a test keeps it true).
const std::vector<std::string>& frameGraphNames();

} // namespace lpv::renderer
