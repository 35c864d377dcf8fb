#include "lpv/renderer/GpuTimer.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace lpv::renderer {

GpuTimer::GpuTimer(std::size_t historyFrames) : historyFrames_(historyFrames) {}

void GpuTimer::synchronizeIfSoftware() {
    if (!softwareChecked_) {
        // Mesa's CPU renderers take a timestamp when they next flush, while they
        // run compute dispatches at once: a pass that starts with a dispatch
        // would lose it (measured: one propagation step timed as 0.1 ms instead
        // of 40). There the "GPU" is the CPU, so flushing at pass boundaries
        // costs nothing it would not cost anyway; on a hardware GPU the timer
        // never stalls.
        const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        software_ = renderer && (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe"));
        softwareChecked_ = true;
    }
    if (software_)
        glFinish();
}

GpuTimer::PassState& GpuTimer::state(const std::string& pass) {
    for (PassState& p : passes_)
        if (p.name == pass)
            return p;
    PassState& p = passes_.emplace_back();
    p.name = pass;
    for (Slot& s : p.ring) {
        s.start = createQuery(GL_TIMESTAMP);
        s.stop = createQuery(GL_TIMESTAMP);
    }
    return p;
}

void GpuTimer::collect(PassState& p, bool wait) {
    // Oldest first, so history stays in frame order.
    for (std::size_t k = 0; k < kLatency; ++k) {
        Slot& s = p.ring[(p.next + k) % kLatency];
        if (!s.pending)
            continue;
        GLint available = GL_FALSE;
        glGetQueryObjectiv(s.stop.id(), GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available && !wait)
            continue;
        GLuint64 t0 = 0, t1 = 0;
        glGetQueryObjectui64v(s.start.id(), GL_QUERY_RESULT, &t0);
        glGetQueryObjectui64v(s.stop.id(), GL_QUERY_RESULT, &t1);
        s.pending = false;
        p.historyMs.push_back(t1 >= t0 ? double(t1 - t0) * 1e-6 : 0.0);
        if (p.historyMs.size() > historyFrames_)
            p.historyMs.pop_front();
    }
}

void GpuTimer::beginFrame() {
    for (PassState& p : passes_)
        collect(p, false);
}

void GpuTimer::begin(const std::string& pass) {
    PassState& p = state(pass);
    Slot& s = p.ring[p.next];
    if (s.pending) // all ring in flight: the GPU is kLatency frames behind; wait rather than lose a sample
        collect(p, true);
    synchronizeIfSoftware();
    glQueryCounter(s.start.id(), GL_TIMESTAMP);
    synchronizeIfSoftware(); // llvmpipe takes a timestamp when it next flushes: now, before the pass's work
}

void GpuTimer::end(const std::string& pass) {
    PassState& p = state(pass);
    Slot& s = p.ring[p.next];
    synchronizeIfSoftware();
    glQueryCounter(s.stop.id(), GL_TIMESTAMP);
    s.pending = true;
    p.next = (p.next + 1) % kLatency;
}

void GpuTimer::resolveAll() {
    for (PassState& p : passes_)
        collect(p, true);
}

void GpuTimer::clearHistory() {
    for (PassState& p : passes_)
        p.historyMs.clear();
}

std::vector<std::pair<std::string, std::vector<double>>> GpuTimer::history() const {
    std::vector<std::pair<std::string, std::vector<double>>> out;
    for (const PassState& p : passes_)
        out.emplace_back(p.name, std::vector<double>(p.historyMs.begin(), p.historyMs.end()));
    return out;
}

std::vector<PassTiming> GpuTimer::table() const {
    std::vector<PassTiming> rows;
    for (const PassState& p : passes_) {
        PassTiming t;
        t.pass = p.name;
        t.samples = p.historyMs.size();
        if (!p.historyMs.empty()) {
            std::vector<double> v(p.historyMs.begin(), p.historyMs.end());
            std::sort(v.begin(), v.end());
            t.minMs = v.front();
            t.maxMs = v.back();
            t.medianMs = v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
            t.lastMs = p.historyMs.back();
        }
        rows.push_back(t);
    }
    return rows;
}

std::string formatTimingTable(const std::vector<PassTiming>& rows) {
    std::string out = "pass                    median ms    min ms    max ms  frames\n";
    char line[160];
    double total = 0.0;
    for (const PassTiming& r : rows) {
        std::snprintf(line, sizeof line, "%-22s %9.3f %9.3f %9.3f %7zu\n", r.pass.c_str(), r.medianMs, r.minMs, r.maxMs,
                      r.samples);
        out += line;
        total += r.medianMs;
    }
    std::snprintf(line, sizeof line, "%-22s %9.3f\n", "total (sum of medians)", total);
    out += line;
    return out;
}

} // namespace lpv::renderer
