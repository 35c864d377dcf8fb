// The Sweeps dock's chart and table on synthetic runs (issue #43): what a
// user reads there, without rendering anything. Time is on a log axis with
// round ticks and each point carries its quartiles as a bar; the axis can
// be GPU memory instead; a run whose mean light is outside 0.8-1.25x the
// reference's is drawn as biased and "Cheapest within" passes it over; the
// detail text and the table give the spread, the memory and the bias.
#include "Document.h"
#include "SweepPanel.h"

#include "lpv/bench/Pareto.h"
#include "lpv/bench/SavedSweep.h"
#include "lpv/renderer/GpuMemory.h"

#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QLabel>
#include <QLineSeries>
#include <QScatterSeries>
#include <QTableWidget>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace lpv::editor;
using lpv::bench::SweepRun;

namespace {

constexpr std::uint64_t kMiB = 1024 * 1024;

SweepRun run(std::vector<lpv::bench::Setting> settings, double median, double q1, double q3,
             std::uint64_t mib, double symmetricError, double meanRatio, double mare) {
    SweepRun r;
    r.settings = std::move(settings);
    r.total = {median, q1, q3, q1 * 0.98, q3 * 1.02, 5};
    r.totalMs = median;
    r.gpuBytes = mib * kMiB;
    r.lpvBytes = mib * kMiB / 2;
    r.indirect.pixels = 1000;
    r.indirect.logError = std::log1p(symmetricError);
    r.indirect.noiseLogError = std::log1p(0.02);
    r.indirect.meanReference = 1.0;
    r.indirect.meanTest = meanRatio;
    r.indirect.mare = mare;
    r.indirect.noiseMare = 0.02;
    return r;
}

// Five settings: the current one; a dark one (0.28x, the Sponza
// steps=2) whose MARE looks best; a slow accurate one that needs little
// memory; one the same cost as the current within the noise but more
// accurate; a bright biased one that is cheap and accurate on its face.
std::shared_ptr<lpv::bench::SavedSweep> syntheticSweep() {
    auto s = std::make_shared<lpv::bench::SavedSweep>();
    s->createdAt = "2026-12-05T00:00:00Z";
    s->width = 64;
    s->height = 36;
    s->runs = {
        run({}, 10.0, 9.5, 10.5, 40, 0.30, 0.95, 0.25),
        run({{"lpv.propagationSteps", "2"}}, 4.0, 3.9, 4.1, 30, 2.60, 0.28, 0.08),
        run({{"lpv.propagationSteps", "16"}}, 40.0, 38.0, 42.0, 15, 0.10, 1.00, 0.12),
        run({{"lpv.gridSize", "64"}}, 10.2, 9.6, 10.8, 200, 0.20, 1.05, 0.18),
        run({{"lpv.intensity", "1.4"}}, 2.0, 1.9, 2.1, 20, 0.08, 1.40, 0.30),
    };
    return s;
}

struct Fixture {
    Document document;
    SweepPanel panel{&document, [] { return lpv::scene::Camera{}; }};
    Fixture() {
        panel.resize(1200, 700);
        panel.showSweep(syntheticSweep());
    }
    QScatterSeries* scatter(const QString& name) {
        for (auto* s : panel.chartView()->chart()->series())
            if (auto* sc = qobject_cast<QScatterSeries*>(s); sc && sc->name() == name)
                return sc;
        return nullptr;
    }
    std::vector<QLineSeries*> spreadBars() {
        std::vector<QLineSeries*> out;
        for (auto* s : panel.chartView()->chart()->series())
            if (auto* l = qobject_cast<QLineSeries*>(s); l && l->name().startsWith("time spread"))
                out.push_back(l);
        return out;
    }
    QCategoryAxis* xAxis() {
        const auto axes = panel.chartView()->chart()->axes(Qt::Horizontal);
        return axes.isEmpty() ? nullptr : qobject_cast<QCategoryAxis*>(axes.front());
    }
};

bool containsPoint(QScatterSeries* s, const QPointF& p) {
    for (const QPointF& q : s->points())
        if (std::abs(q.x() - p.x()) < 1e-9 && std::abs(q.y() - p.y()) < 1e-9)
            return true;
    return false;
}

} // namespace

TEST(SweepChart, TimeIsOnALogAxisWithRoundTicksAndQuartileBars) {
    Fixture f;
    QCategoryAxis* axis = f.xAxis();
    ASSERT_NE(axis, nullptr);
    EXPECT_TRUE(axis->titleText().contains("log")) << axis->titleText().toStdString();
    const QStringList labels = axis->categoriesLabels();
    ASSERT_GE(labels.size(), 3) << "round ticks inside 2..40 ms";
    for (const QString& label : labels) {
        bool ok = false;
        const double v = label.toDouble(&ok);
        ASSERT_TRUE(ok && v > 0.0) << label.toStdString();
        const double mantissa = v / std::pow(10.0, std::floor(std::log10(v) + 1e-9));
        EXPECT_TRUE(std::abs(mantissa - 1.0) < 1e-6 || std::abs(mantissa - 2.0) < 1e-6 ||
                    std::abs(mantissa - 5.0) < 1e-6)
            << "a round tick: " << label.toStdString();
        EXPECT_NEAR(axis->endValue(label), std::log10(v), 1e-9) << "placed on log10 of its value";
        EXPECT_GE(axis->endValue(label), axis->min());
        EXPECT_LE(axis->endValue(label), axis->max());
    }
    EXPECT_LE(axis->min(), std::log10(2.0)) << "the cheapest point inside";
    EXPECT_GE(axis->max(), std::log10(42.0)) << "the dearest point's quartile inside";
    // Each point at log10 of its median, y the symmetric error in percent.
    const auto& runs = f.panel.sweep()->runs;
    for (int i = 0; i < int(runs.size()); ++i) {
        const auto p = f.panel.plottedPoint(i);
        ASSERT_TRUE(p.has_value());
        EXPECT_NEAR(p->x(), std::log10(runs[std::size_t(i)].total.median), 1e-9);
        EXPECT_NEAR(p->y(), 100.0 * runs[std::size_t(i)].indirect.symmetricError(), 1e-9);
        EXPECT_DOUBLE_EQ(f.panel.costOf(i), runs[std::size_t(i)].total.median);
    }
    // A bar from q1 to q3 through every point.
    const auto bars = f.spreadBars();
    ASSERT_EQ(bars.size(), runs.size());
    for (QLineSeries* bar : bars) {
        ASSERT_EQ(bar->count(), 2);
        const double y = bar->at(0).y();
        EXPECT_EQ(bar->at(1).y(), y);
        const auto it = std::ranges::find_if(runs, [&](const SweepRun& r) {
            return std::abs(100.0 * r.indirect.symmetricError() - y) < 1e-9;
        });
        ASSERT_NE(it, runs.end());
        EXPECT_NEAR(bar->at(0).x(), std::log10(it->total.q1), 1e-9);
        EXPECT_NEAR(bar->at(1).x(), std::log10(it->total.q3), 1e-9);
    }
}

TEST(SweepChart, MemoryAxisPlotsGpuBytes) {
    Fixture f;
    f.panel.axisBox()->setCurrentIndex(1);
    ASSERT_EQ(f.panel.costAxis(), SweepPanel::CostAxis::Memory);
    EXPECT_TRUE(f.xAxis()->titleText().contains("memory")) << f.xAxis()->titleText().toStdString();
    const auto& runs = f.panel.sweep()->runs;
    for (int i = 0; i < int(runs.size()); ++i) {
        const double mib = double(runs[std::size_t(i)].gpuBytes) / double(kMiB);
        EXPECT_DOUBLE_EQ(f.panel.costOf(i), mib);
        ASSERT_TRUE(f.panel.plottedPoint(i).has_value());
        EXPECT_NEAR(f.panel.plottedPoint(i)->x(), std::log10(mib), 1e-9);
    }
    EXPECT_TRUE(f.spreadBars().empty()) << "bytes are exact: no bars";
    // The front is memory's: the slow accurate run (15 MiB, 10%) is on it
    // beside the bright biased one (20 MiB, 8%); on time the biased one (2 ms) alone.
    EXPECT_EQ(f.panel.front(), (std::vector<bool>{false, false, true, false, true}));
    f.panel.axisBox()->setCurrentIndex(0);
    EXPECT_NEAR(f.panel.plottedPoint(2)->x(), std::log10(40.0), 1e-9) << "back to time";
    EXPECT_EQ(f.panel.front(), (std::vector<bool>{false, false, false, false, true}));
}

TEST(SweepChart, BiasedRunsAreMarkedAndNotChosen) {
    Fixture f;
    QScatterSeries* biased = f.scatter("biased (mean outside 0.8-1.25x)");
    ASSERT_NE(biased, nullptr);
    EXPECT_EQ(biased->count(), 2);
    EXPECT_TRUE(containsPoint(biased, *f.panel.plottedPoint(1)));
    EXPECT_TRUE(containsPoint(biased, *f.panel.plottedPoint(4)));
    EXPECT_EQ(biased->color(), QColor(235, 140, 20)) << "orange";
    for (const QString& name : {QString("settings"), QString("on the front")}) {
        QScatterSeries* s = f.scatter(name);
        ASSERT_NE(s, nullptr);
        EXPECT_FALSE(containsPoint(s, *f.panel.plottedPoint(1))) << name.toStdString();
    }

    // Every run is within 300%; the biased cheap ones are passed over, and of
    // the two the same cost within the noise (10.0 and 10.2 ms) the more accurate wins.
    EXPECT_EQ(f.panel.selectCheapestWithin(300.0), 3);
    EXPECT_EQ(f.panel.selectCheapestWithin(16.0), 2);
    // Only the bright biased run reaches 9%: nothing is chosen, and it says why.
    EXPECT_EQ(f.panel.selectCheapestWithin(9.0), -1);
    EXPECT_TRUE(f.panel.detailText()->text().contains("Only biased"))
        << f.panel.detailText()->text().toStdString();
    EXPECT_EQ(f.panel.selectCheapestWithin(5.0), -1);
    EXPECT_TRUE(f.panel.detailText()->text().contains("No setting"))
        << f.panel.detailText()->text().toStdString();
    // On memory the cheapest unbiased within 300% is the 15 MiB one, not the 20 MiB bright one.
    f.panel.setCostAxis(SweepPanel::CostAxis::Memory);
    EXPECT_EQ(f.panel.selectCheapestWithin(300.0), 2);
    EXPECT_EQ(f.panel.selectCheapestWithin(40.0), 2);
}

TEST(SweepChart, DetailAndTableShowSpreadMemoryAndBias) {
    Fixture f;
    const auto& runs = f.panel.sweep()->runs;
    f.panel.showRun(1);
    const QString dark = f.panel.detailText()->text();
    EXPECT_TRUE(dark.contains("mean 0.28x: biased")) << dark.toStdString();
    EXPECT_TRUE(dark.contains("4.00 ms ±0.10 over 5 rounds")) << dark.toStdString();
    EXPECT_TRUE(dark.contains(QString::fromStdString(lpv::renderer::formatBytes(runs[1].gpuBytes))))
        << dark.toStdString();
    EXPECT_TRUE(dark.contains("260.0%")) << "the symmetric error: " << dark.toStdString();
    EXPECT_TRUE(dark.contains("MARE 8.0%")) << dark.toStdString();

    f.panel.showRun(0);
    const QString current = f.panel.detailText()->text();
    EXPECT_TRUE(current.contains("10.00 ms ±0.50 over 5 rounds")) << current.toStdString();
    EXPECT_TRUE(current.contains("same cost within the noise as gridSize=64")) << current.toStdString();
    EXPECT_TRUE(current.contains("mean 0.95x")) << current.toStdString();
    EXPECT_FALSE(current.contains("biased")) << current.toStdString();

    QTableWidget* table = f.panel.runsTable();
    ASSERT_EQ(table->rowCount(), int(runs.size()));
    auto header = [&](int c) { return table->horizontalHeaderItem(c)->text(); };
    int time = -1, memory = -1, error = -1, mean = -1, same = -1;
    for (int c = 0; c < table->columnCount(); ++c) {
        time = header(c) == "GPU time" ? c : time;
        memory = header(c) == "GPU memory" ? c : memory;
        error = header(c) == "Error" ? c : error;
        mean = header(c) == "Mean" ? c : mean;
        same = header(c) == "Same cost as" ? c : same;
    }
    ASSERT_TRUE(time >= 0 && memory >= 0 && error >= 0 && mean >= 0 && same >= 0);
    EXPECT_EQ(table->item(0, time)->text(), "10.00 ms ±0.50");
    EXPECT_TRUE(table->item(0, time)->toolTip().contains("over 5 rounds"))
        << table->item(0, time)->toolTip().toStdString();
    EXPECT_EQ(table->item(0, same)->text(), "4") << "row 4: the grid run";
    EXPECT_EQ(table->item(1, memory)->text(), "30 MiB");
    EXPECT_EQ(table->item(1, error)->text(), "260.0%");
    EXPECT_EQ(table->item(1, mean)->text(), "0.28x biased");
    EXPECT_EQ(table->item(2, mean)->text(), "1.00x");
}
