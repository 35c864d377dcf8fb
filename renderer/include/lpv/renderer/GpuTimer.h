#pragma once
// Per-pass GPU timing with timestamp queries. Results are read a few frames
// later, only once the GPU reports them available, so timing never stalls
// the pipeline. Statistics are median/min/max over the last N frames.
#include "lpv/renderer/GlHandle.h"

#include <array>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace lpv::renderer {

struct PassTiming {
    std::string pass;
    double medianMs = 0.0;
    double minMs = 0.0;
    double maxMs = 0.0;
    double lastMs = 0.0;
    std::size_t samples = 0;
};

class GpuTimer {
public:
    explicit GpuTimer(std::size_t historyFrames = 120);

    // Call once per frame before any begin(); collects finished queries.
    void beginFrame();
    void begin(const std::string& pass);
    void end(const std::string& pass);
    // Forgets the collected times (e.g. after warm-up frames); queries in flight are kept.
    void clearHistory();
    // Blocks until every query issued so far has a result (use at exit, not per frame).
    void resolveAll();

    // In the order passes were first seen.
    std::vector<PassTiming> table() const;
    // Each pass's time per frame (ms), oldest first, over the last N frames.
    std::vector<std::pair<std::string, std::vector<double>>> history() const;

private:
    static constexpr std::size_t kLatency = 4; // frames in flight per pass
    struct Slot {
        Query start, stop;
        bool pending = false;
    };
    struct PassState {
        std::string name;
        std::array<Slot, kLatency> ring;
        std::size_t next = 0;
        std::deque<double> historyMs;
    };
    PassState& state(const std::string& pass);
    void collect(PassState& p, bool wait);
    // glFinish at pass boundaries on llvmpipe/softpipe only (see GpuTimer.cpp).
    void synchronizeIfSoftware();

    std::vector<PassState> passes_;
    std::size_t historyFrames_;
    bool softwareChecked_ = false;
    bool software_ = false;
};

// A table as text: pass, median, min, max (ms), samples.
std::string formatTimingTable(const std::vector<PassTiming>& rows);

} // namespace lpv::renderer
