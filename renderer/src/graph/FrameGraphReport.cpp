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

namespace {

// `name` with a note in parentheses kept outside the code span: `lpv.volumes` (updated).
std::string codeName(const std::string& name) {
    const std::size_t note = name.find(" (");
    return note == std::string::npos ? "`" + name + "`" : "`" + name.substr(0, note) + "`" + name.substr(note);
}

} // namespace

std::string formatGraphMarkdown(const FrameGraphReport& report) {
    std::string out = "| pass | reads | writes |\n|---|---|---|\n";
    for (const GraphPassReport& p : report.passes) {
        std::string reads, writes;
        for (const std::string& r : p.reads)
            reads += (reads.empty() ? "" : ", ") + codeName(r);
        for (const GraphResourceUse& w : p.writes)
            writes += (writes.empty() ? "" : ", ") + codeName(w.name);
        out += "| `" + p.name + "` | " + reads + " | " + writes + " |\n";
    }
    return out;
}

} // namespace lpv::renderer
