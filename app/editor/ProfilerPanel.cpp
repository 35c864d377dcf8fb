#include "ProfilerPanel.h"

#include <QChart>
#include <QChartView>
#include <QHeaderView>
#include <QLineSeries>
#include <QSplitter>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace lpv::editor {

namespace {

// The table and chart redraw at most this often; frames in between only
// append to the history. Ten redraws a second reads as live without the
// chart costing more than the frames it measures.
constexpr qint64 kDrawIntervalMs = 100;

enum Column { kPass, kLast, kMedian, kMin, kMax, kShare, kColumns };

QString ms(double v) {
    return QString::number(v, 'f', 3);
}

// 1, 2, 2.5 or 5 times a power of ten, at least v: axis ends that read well.
double niceCeiling(double v) {
    if (v <= 0.0)
        return 1.0;
    const double p = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
        if (m * p >= v)
            return m * p;
    return 10.0 * p;
}

} // namespace

ProfilerPanel::ProfilerPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    // Table and chart side by side: stacked, they made the dock a third of a
    // 900 px window's height and the viewport small (issue #46).
    auto* split = new QSplitter(Qt::Horizontal, this);
    layout->addWidget(split);

    table_ = new QTableWidget(0, kColumns, split);
    table_->setObjectName("profilerTable");
    table_->setHorizontalHeaderLabels(
        {tr("Pass"), tr("Last (ms)"), tr("Median (ms)"), tr("Min (ms)"), tr("Max (ms)"), tr("Share")});
    table_->horizontalHeaderItem(kShare)->setToolTip(tr("The pass's median as a share of the frame's"));
    table_->verticalHeader()->hide();
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionMode(QAbstractItemView::NoSelection);
    table_->horizontalHeader()->setSectionResizeMode(kPass, QHeaderView::Stretch);
    for (int c = kLast; c < kColumns; ++c)
        table_->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);

    chart_ = new QChart();
    chart_->setAnimationOptions(QChart::NoAnimation);
    chart_->legend()->setAlignment(Qt::AlignRight); // beside the plot: the dock is a short strip
    chart_->setMargins(QMargins(4, 4, 4, 4));
    axisX_ = new QValueAxis(chart_);
    axisX_->setRange(-kWindowSeconds, 0.0);
    axisX_->setLabelFormat("%.0f");
    axisX_->setTickCount(6); // every 2 s
    axisX_->setTitleText(tr("seconds ago"));
    axisY_ = new QValueAxis(chart_);
    axisY_->setRange(0.0, 1.0);
    axisY_->setLabelFormat("%.1f");
    axisY_->setTitleText(tr("GPU ms"));
    chart_->addAxis(axisX_, Qt::AlignBottom);
    chart_->addAxis(axisY_, Qt::AlignLeft);
    view_ = new QChartView(chart_, split); // takes ownership of the chart
    view_->setObjectName("profilerChart");
    view_->setMinimumHeight(140);
    view_->setMinimumWidth(240);
    split->addWidget(table_);
    split->addWidget(view_);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    split->setSizes({450, 450}); // half each

    pending_ = new QTimer(this);
    pending_->setSingleShot(true);
    connect(pending_, &QTimer::timeout, this, &ProfilerPanel::refreshNow);
    clock_.start();
    track(QString::fromLatin1(kFrameName));
}

ProfilerPanel::~ProfilerPanel() = default;

QLineSeries* ProfilerPanel::series(const QString& name) const {
    for (const Track& t : tracks_)
        if (t.name == name)
            return t.series;
    return nullptr;
}

ProfilerPanel::Track& ProfilerPanel::track(const QString& name) {
    for (Track& t : tracks_)
        if (t.name == name)
            return t;
    tracks_.push_back(Track{name, {}, nullptr});
    return tracks_.back();
}

void ProfilerPanel::addFrame(const std::vector<renderer::PassTiming>& table) {
    // A row without a sample has no time yet (its query is still in flight):
    // counted as 0 ms it would make the frame's minimum read 0.
    std::vector<renderer::PassTiming> measured;
    for (const renderer::PassTiming& p : table)
        if (p.samples > 0)
            measured.push_back(p);
    if (measured.empty())
        return;
    const double now = double(clock_.nsecsElapsed()) * 1e-9;
    double frameMs = 0.0;
    for (const renderer::PassTiming& p : measured) {
        frameMs += p.lastMs;
        track(QString::fromStdString(p.pass)).samples.push_back({now, p.lastMs});
    }
    tracks_.front().samples.push_back({now, frameMs});
    last_ = std::move(measured);
    for (Track& t : tracks_)
        while (!t.samples.empty() && now - t.samples.front().t > kWindowSeconds)
            t.samples.pop_front();

    // Hidden: the history above is all the work a frame costs.
    if (!isVisible())
        return;
    const qint64 since = sinceDraw_.isValid() ? sinceDraw_.elapsed() : kDrawIntervalMs;
    if (since >= kDrawIntervalMs)
        refreshNow();
    else if (!pending_->isActive())
        pending_->start(int(kDrawIntervalMs - since));
}

void ProfilerPanel::clear() {
    pending_->stop();
    last_.clear();
    for (Track& t : tracks_) {
        if (t.series) {
            chart_->removeSeries(t.series);
            delete t.series;
        }
    }
    tracks_.clear();
    track(QString::fromLatin1(kFrameName));
    table_->setRowCount(0);
    axisY_->setRange(0.0, 1.0);
}

void ProfilerPanel::refreshNow() {
    pending_->stop();
    sinceDraw_.start();
    updateTable();
    updateChart();
}

void ProfilerPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    refreshNow();
}

void ProfilerPanel::updateTable() {
    // The frame row uses the panel's own history of frame totals: the sum of
    // the passes' medians is not the median of their sums.
    std::vector<double> frames;
    for (const Sample& s : tracks_.front().samples)
        frames.push_back(s.ms);
    double frameMedian = 0.0, frameMin = 0.0, frameMax = 0.0, frameLast = 0.0;
    if (!frames.empty()) {
        frameLast = frames.back();
        std::sort(frames.begin(), frames.end());
        frameMedian = frames[frames.size() / 2];
        frameMin = frames.front();
        frameMax = frames.back();
    }
    double medianSum = 0.0;
    for (const renderer::PassTiming& p : last_)
        medianSum += p.medianMs;

    auto cell = [this](int row, int column, const QString& text) {
        QTableWidgetItem* item = table_->item(row, column);
        if (!item) {
            item = new QTableWidgetItem;
            if (column != kPass)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            table_->setItem(row, column, item);
        }
        if (item->text() != text)
            item->setText(text);
        return item;
    };
    const int rows = last_.empty() ? 0 : int(last_.size()) + 1;
    table_->setRowCount(rows);
    for (std::size_t i = 0; i < last_.size(); ++i) {
        const renderer::PassTiming& p = last_[i];
        const int row = int(i);
        cell(row, kPass, QString::fromStdString(p.pass));
        cell(row, kLast, ms(p.lastMs));
        cell(row, kMedian, ms(p.medianMs));
        cell(row, kMin, ms(p.minMs));
        cell(row, kMax, ms(p.maxMs));
        cell(row, kShare,
             medianSum > 0.0 ? QStringLiteral("%1 %").arg(100.0 * p.medianMs / medianSum, 0, 'f', 1)
                             : QStringLiteral("-"));
    }
    if (rows == 0)
        return;
    const int row = rows - 1;
    QTableWidgetItem* name = cell(row, kPass, tr("%1 (all passes)").arg(QString::fromLatin1(kFrameName)));
    QFont bold = name->font();
    bold.setBold(true);
    name->setFont(bold);
    cell(row, kLast, ms(frameLast));
    cell(row, kMedian, ms(frameMedian));
    cell(row, kMin, ms(frameMin));
    cell(row, kMax, ms(frameMax));
    cell(row, kShare, QStringLiteral("100 %"));
}

void ProfilerPanel::updateChart() {
    const double now = double(clock_.nsecsElapsed()) * 1e-9;
    double maxMs = 0.0;
    for (std::size_t i = 0; i < tracks_.size();) {
        Track& t = tracks_[i];
        // A pass that stopped running (its effect was switched off) leaves once its history is old.
        if (t.samples.empty() && i > 0) {
            if (t.series) {
                chart_->removeSeries(t.series);
                delete t.series;
            }
            tracks_.erase(tracks_.begin() + std::ptrdiff_t(i));
            continue;
        }
        if (!t.series) {
            t.series = new QLineSeries(chart_);
            t.series->setName(t.name);
            chart_->addSeries(t.series);
            t.series->attachAxis(axisX_);
            t.series->attachAxis(axisY_);
            if (i == 0) {
                QPen pen = t.series->pen();
                pen.setWidthF(2.5);
                t.series->setPen(pen);
            }
        }
        QList<QPointF> points;
        points.reserve(qsizetype(t.samples.size()));
        for (const Sample& s : t.samples) {
            points.append(QPointF(s.t - now, s.ms));
            maxMs = std::max(maxMs, s.ms);
        }
        t.series->replace(points);
        ++i;
    }
    axisY_->setRange(0.0, niceCeiling(maxMs * 1.1));
}

} // namespace lpv::editor
