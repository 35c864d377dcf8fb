#include "lpv/renderer/FrameGraphReport.h"

namespace lpv::renderer {

const char* toString(PassStatus status) {
    switch (status) {
    case PassStatus::Ran: return "ran";
    case PassStatus::Reused: return "reused";
    case PassStatus::Culled: return "culled";
    }
    return "?";
}

const GraphPassReport* FrameGraphReport::find(const std::string& pass) const {
    for (const GraphPassReport& p : passes)
        if (p.name == pass)
            return &p;
    return nullptr;
}

std::string formatGraph(const FrameGraphReport& report) {
    std::string out;
    for (const GraphPassReport& p : report.passes) {
        out += p.name + ": " + toString(p.status) + " (" + p.reason + ")\n";
        if (p.status == PassStatus::Culled)
            continue;
        if (!p.reads.empty()) {
            out += "    reads ";
            for (std::size_t i = 0; i < p.reads.size(); ++i)
                out += (i ? ", " : "") + p.reads[i];
            out += "\n";
        }
        for (const GraphResourceUse& w : p.writes)
            out += "    writes " + w.name + ": " + w.description + "\n";
    }
    return out;
}

} // namespace lpv::renderer
