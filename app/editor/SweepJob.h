#pragma once
// A sweep run from the editor (issue #26 item 4) on a thread of its own,
// with its own headless GL context (bench::runSweep), so the viewport keeps
// drawing: it traces the references the settings need (one per lpv.bounces
// and per choice of lights the reference must trace to be like for like),
// times and measures every setting, and reports progress with an estimate of
// the time left. Results arrive on the GUI thread, one run at a time.
#include "lpv/bench/MeasuredSweep.h"
#include "lpv/bench/SavedSweep.h"

#include <QImage>
#include <QObject>
#include <QString>

#include <atomic>
#include <filesystem>
#include <memory>
#include <thread>

namespace lpv::editor {

// What to sweep: the document's project (its parameters are the base), the
// view, the combinations ({} = the current settings), size, frames, spp.
using SweepJobSpec = bench::MeasuredSweepSpec;

class SweepJob : public QObject {
    Q_OBJECT
public:
    explicit SweepJob(QObject* parent = nullptr);
    ~SweepJob() override; // stops the run in flight and waits for it

    // Starts a sweep; false when one is already running.
    bool start(SweepJobSpec spec);
    // Stops after the pass or setting in flight; `failed` follows with "stopped".
    void cancel() { cancel_ = true; }
    bool running() const { return running_; }

signals:
    // 0..1 of the whole job, and what it is doing ("Reference 1 of 2: 96/512 spp").
    void progress(double fraction, const QString& text);
    // Run `index` of the spec's combinations, with a preview of its indirect light.
    void runFinished(int index, const lpv::bench::SweepRun& run, const QImage& preview);
    // `timing`: how the times were taken ("3 rounds (spread within 10% after 3 rounds), load 0.10 ... ->
    // ...").
    void finished(std::shared_ptr<const lpv::bench::SavedSweep> sweep, const QString& timing);
    void failed(const QString& message, bool cancelled);

private:
    void run(SweepJobSpec spec);
    void post(std::function<void()> onGui);

    std::thread worker_;
    std::atomic<bool> cancel_{false};
    std::atomic<bool> running_{false};
};

// A preview (RGBA8 or RGB8) as a QImage that owns its pixels.
QImage toQImage(const scene::Image8& image);

} // namespace lpv::editor
