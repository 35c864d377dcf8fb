#include "SweepPanel.h"

#include "Document.h"

#include "lpv/bench/Pareto.h"
#include "lpv/bench/Questions.h"

#include <QChart>
#include <QChartView>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineSeries>
#include <QPainter>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace lpv::editor {

namespace {

// Checked by default: the questions that are cheap to ask of any scene and
// need no reference of their own. The others (RSM size, variants, sky,
// bounces, ...) are one click away; bounces and sky trace extra references.
const char* const kDefaultQuestions[] = {"steps", "grid", "cascades", "occlusion", "directed", "damping",
                                         "strength", "visibility"};

enum QuestionColumn { kQuestion, kValues };

QString percent(double v) {
    return QString::number(100.0 * v, 'f', 1) + "%";
}

QString labelOf(const std::vector<bench::Setting>& settings) {
    return settings.empty() ? QObject::tr("current settings") : QString::fromStdString(bench::sweepLabel(settings));
}

} // namespace

SweepPanel::SweepPanel(Document* document, std::function<scene::Camera()> currentView, QWidget* parent)
    : QWidget(parent), document_(document), currentView_(std::move(currentView)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* split = new QSplitter(Qt::Horizontal, this);
    layout->addWidget(split);

    // Left: what to sweep and how.
    auto* setup = new QWidget(split);
    auto* setupLayout = new QVBoxLayout(setup);
    setupLayout->setContentsMargins(0, 0, 0, 0);
    questions_ = new QTableWidget(0, 2, setup);
    questions_->setObjectName("sweepQuestions");
    questions_->setHorizontalHeaderLabels({tr("Question"), tr("Values (KEY=V1,V2,...)")});
    questions_->verticalHeader()->hide();
    questions_->horizontalHeader()->setSectionResizeMode(kValues, QHeaderView::Stretch);
    questions_->setToolTip(tr("Each checked row varies one parameter alone around the current settings"));
    setupLayout->addWidget(questions_, 1);
    buildQuestions();
    auto* addRow = new QPushButton(tr("Add a row"), setup);
    connect(addRow, &QPushButton::clicked, this, [this] {
        const int row = questions_->rowCount();
        questions_->insertRow(row);
        auto* name = new QTableWidgetItem(tr("custom"));
        name->setCheckState(Qt::Checked);
        questions_->setItem(row, kQuestion, name);
        questions_->setItem(row, kValues, new QTableWidgetItem("lpv.propagationSteps=4,8"));
        questions_->editItem(questions_->item(row, kValues));
    });
    setupLayout->addWidget(addRow);

    auto* form = new QFormLayout();
    auto spin = [this](int lo, int hi, int value, const QString& suffix, const QString& tip) {
        auto* s = new QSpinBox(this);
        s->setRange(lo, hi);
        s->setValue(value);
        s->setSuffix(suffix);
        s->setToolTip(tip);
        return s;
    };
    auto* size = new QHBoxLayout();
    width_ = spin(16, 3840, 160, " px", tr("Width of the measured image"));
    height_ = spin(16, 2160, 90, " px", tr("Height of the measured image"));
    size->addWidget(width_);
    size->addWidget(new QLabel("x", this));
    size->addWidget(height_);
    form->addRow(tr("Image"), size);
    frames_ = spin(1, 1000, 3, "", tr("Timed frames per setting (the median is plotted)"));
    warmup_ = spin(0, 100, 1, "", tr("Untimed frames before them"));
    auto* frames = new QHBoxLayout();
    frames->addWidget(frames_);
    frames->addWidget(new QLabel(tr("after warm-up"), this));
    frames->addWidget(warmup_);
    form->addRow(tr("Frames"), frames);
    spp_ = spin(1, 65536, 512, " spp",
                tr("Samples per pixel of the path-traced reference: more lowers its own noise, "
                   "shown as a line in the plot"));
    form->addRow(tr("Reference"), spp_);
    setupLayout->addLayout(form);

    auto* buttons = new QHBoxLayout();
    run_ = new QPushButton(tr("Run sweep"), setup);
    run_->setObjectName("sweepRun");
    stop_ = new QPushButton(tr("Stop"), setup);
    stop_->setEnabled(false);
    buttons->addWidget(run_);
    buttons->addWidget(stop_);
    setupLayout->addLayout(buttons);
    progress_ = new QProgressBar(setup);
    progress_->setRange(0, 1000);
    progress_->setTextVisible(false);
    setupLayout->addWidget(progress_);
    status_ = new QLabel(tr("No sweep yet"), setup);
    status_->setWordWrap(true);
    setupLayout->addWidget(status_);
    connect(run_, &QPushButton::clicked, this, &SweepPanel::startSweep);
    connect(stop_, &QPushButton::clicked, this, &SweepPanel::stopSweep);

    // Middle: the plot.
    chart_ = new QChart();
    chart_->setAnimationOptions(QChart::NoAnimation);
    chart_->setTitle(tr("Indirect light error against GPU time"));
    axisX_ = new QValueAxis(chart_);
    axisX_->setTitleText(tr("GPU ms per frame (sum of pass medians)"));
    axisY_ = new QValueAxis(chart_);
    axisY_->setTitleText(tr("indirect MARE %"));
    chart_->addAxis(axisX_, Qt::AlignBottom);
    chart_->addAxis(axisY_, Qt::AlignLeft);
    auto addSeries = [this](QXYSeries* s, const QString& name) {
        s->setName(name);
        chart_->addSeries(s);
        s->attachAxis(axisX_);
        s->attachAxis(axisY_);
    };
    noiseLine_ = new QLineSeries(chart_);
    noiseLine_->setPen(QPen(Qt::gray, 1, Qt::DashLine));
    addSeries(noiseLine_, tr("reference noise"));
    frontLine_ = new QLineSeries(chart_);
    frontLine_->setPen(QPen(QColor(200, 60, 40), 1.5));
    addSeries(frontLine_, tr("Pareto front"));
    allPoints_ = new QScatterSeries(chart_);
    allPoints_->setMarkerSize(8);
    allPoints_->setColor(QColor(40, 110, 180));
    addSeries(allPoints_, tr("settings"));
    frontPoints_ = new QScatterSeries(chart_);
    frontPoints_->setMarkerSize(10);
    frontPoints_->setColor(QColor(200, 60, 40));
    addSeries(frontPoints_, tr("on the front"));
    currentPoints_ = new QScatterSeries(chart_);
    currentPoints_->setMarkerShape(QScatterSeries::MarkerShapeStar);
    currentPoints_->setMarkerSize(18);
    currentPoints_->setColor(QColor(240, 190, 20));
    addSeries(currentPoints_, tr("current"));
    selectedPoint_ = new QScatterSeries(chart_);
    selectedPoint_->setMarkerSize(20);
    selectedPoint_->setColor(Qt::transparent);
    selectedPoint_->setBorderColor(Qt::black);
    addSeries(selectedPoint_, tr("selected"));
    for (QScatterSeries* s : {allPoints_, frontPoints_, currentPoints_, selectedPoint_}) {
        connect(s, &QScatterSeries::hovered, this, [this](const QPointF& p, bool on) {
            if (on)
                showRun(runAt(p));
        });
        // Applying rebuilds the series; not inside the series' own mouse event.
        connect(s, &QScatterSeries::clicked, this, [this](const QPointF& p) {
            const int index = runAt(p);
            QMetaObject::invokeMethod(this, [this, index] { applyRun(index); }, Qt::QueuedConnection);
        });
    }
    chartView_ = new QChartView(chart_, split);
    chartView_->setRenderHint(QPainter::Antialiasing);
    chartView_->setMinimumWidth(320);

    // Right: the hovered or selected point.
    auto* detail = new QWidget(split);
    auto* detailLayout = new QVBoxLayout(detail);
    detailLayout->setContentsMargins(0, 0, 0, 0);
    auto* cheapest = new QHBoxLayout();
    maxError_ = new QDoubleSpinBox(detail);
    maxError_->setRange(0.1, 100000.0);
    maxError_->setValue(10.0);
    maxError_->setSuffix(" %");
    maxError_->setToolTip(tr("Indirect MARE bound"));
    auto* pick = new QPushButton(tr("Cheapest within"), detail);
    pick->setToolTip(tr("Select the fastest setting whose indirect error is at most this"));
    connect(pick, &QPushButton::clicked, this, [this] { selectCheapestWithin(maxError_->value()); });
    cheapest->addWidget(pick);
    cheapest->addWidget(maxError_);
    detailLayout->addLayout(cheapest);
    auto* apply = new QPushButton(tr("Apply selected"), detail);
    apply->setToolTip(tr("Make the selected setting the project's (one undoable edit)"));
    connect(apply, &QPushButton::clicked, this, [this] { applyRun(selected_); });
    detailLayout->addWidget(apply);
    detailText_ = new QLabel(tr("Hover a point to see its settings; click it to apply them."), detail);
    detailText_->setWordWrap(true);
    detailText_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    detailLayout->addWidget(detailText_);
    detailImage_ = new QLabel(detail);
    detailImage_->setToolTip(tr("Indirect light: the reference (left) and the setting (right), exposed alike"));
    detailLayout->addWidget(detailImage_);
    detailLayout->addStretch(1);
    split->setStretchFactor(1, 1);

    connect(&job_, &SweepJob::progress, this, [this](double f, const QString& text) {
        progress_->setValue(int(std::lround(1000.0 * std::clamp(f, 0.0, 1.0))));
        status_->setText(text);
    });
    connect(&job_, &SweepJob::runFinished, this, &SweepPanel::onRunFinished);
    connect(&job_, &SweepJob::finished, this, &SweepPanel::onFinished);
    connect(&job_, &SweepJob::failed, this, &SweepPanel::onFailed);
    connect(document_, &Document::changed, this, [this](Changes changes) {
        if (changes == Changes(Change::Everything))
            onDocumentChanged(true);
        else if (changes & Change::Parameters)
            onDocumentChanged(false);
    });
    connect(document_, &Document::projectSaved, this, &SweepPanel::saveBesideProject);
    loadBesideProject();
}

SweepPanel::~SweepPanel() = default;

void SweepPanel::buildQuestions() {
    for (const bench::Question& q : bench::reportQuestions()) {
        const int row = questions_->rowCount();
        questions_->insertRow(row);
        auto* name = new QTableWidgetItem(QString::fromStdString(q.name));
        name->setFlags(name->flags() & ~Qt::ItemIsEditable);
        name->setCheckState(std::ranges::find(kDefaultQuestions, q.name) != std::end(kDefaultQuestions)
                                ? Qt::Checked
                                : Qt::Unchecked);
        questions_->setItem(row, kQuestion, name);
        questions_->setItem(row, kValues, new QTableWidgetItem(QString::fromStdString(q.sweep)));
    }
    questions_->resizeColumnToContents(kQuestion);
}

std::optional<std::vector<std::vector<bench::Setting>>> SweepPanel::plannedCombinations(QString& error) const {
    const scene::ParameterSet& current = document_->parameters();
    std::vector<std::vector<bench::Setting>> combinations{{}};
    for (int row = 0; row < questions_->rowCount(); ++row) {
        const QTableWidgetItem* name = questions_->item(row, kQuestion);
        const QTableWidgetItem* values = questions_->item(row, kValues);
        if (!name || name->checkState() != Qt::Checked || !values)
            continue;
        std::string planError;
        bench::SetPlan plan = bench::planSettings({values->text().trimmed().toStdString()}, planError);
        if (!planError.empty()) {
            error = tr("Row \"%1\": %2").arg(name->text(), QString::fromStdString(planError));
            return std::nullopt;
        }
        std::vector<std::vector<bench::Setting>> rows = plan.combinations;
        for (const bench::Setting& one : plan.fixed) // a single value is still a question
            rows.push_back({one});
        if (auto bad = bench::checkCombinations({{}, rows}, current, "sweep")) {
            error = tr("Row \"%1\": %2").arg(name->text(), QString::fromStdString(*bad));
            return std::nullopt;
        }
        for (auto& combination : rows) {
            scene::ParameterSet p = current;
            for (const auto& [key, value] : combination)
                (void)p.setFromText(key, value, "sweep");
            // The current settings are run once, as {}: no second point on top of it.
            const bool isCurrent = bench::sameValues(p, current);
            const bool seen = std::ranges::find(combinations, combination) != combinations.end();
            if (!isCurrent && !seen)
                combinations.push_back(std::move(combination));
        }
    }
    return combinations;
}

void SweepPanel::setSweepSize(int width, int height, int frames, int warmup, int referenceSpp) {
    width_->setValue(width);
    height_->setValue(height);
    frames_->setValue(frames);
    warmup_->setValue(warmup);
    spp_->setValue(referenceSpp);
}

QString SweepPanel::statusText() const {
    return status_->text();
}

bool SweepPanel::sweepRunning() const {
    return job_.running();
}

void SweepPanel::startSweep() {
    if (job_.running())
        return;
    QString error;
    auto combinations = plannedCombinations(error);
    if (!combinations) {
        status_->setText(error);
        emit logMessage(tr("Sweep not started: %1").arg(error), true);
        return;
    }
    SweepJobSpec spec;
    spec.project = document_->project();
    spec.projectDir = document_->projectDir().toStdString();
    spec.projectFile = document_->path().toStdString();
    spec.camera = currentView_();
    spec.combinations = *combinations;
    spec.width = width_->value();
    spec.height = height_->value();
    spec.frames = frames_->value();
    spec.warmup = warmup_->value();
    spec.referenceSpp = spp_->value();
    runningCombinations_ = spec.combinations;
    partialRuns_.assign(spec.combinations.size(), std::nullopt);
    previews_.assign(spec.combinations.size(), QImage());
    sweep_.reset();
    selected_ = -1;
    rebuildChart();
    if (!job_.start(std::move(spec)))
        return;
    run_->setEnabled(false);
    stop_->setEnabled(true);
    progress_->setValue(0);
    emit timingChanged(true);
    status_->setText(tr("Starting: %1 settings").arg(runningCombinations_.size()));
}

void SweepPanel::stopSweep() {
    job_.cancel();
    status_->setText(tr("Stopping after the setting in flight..."));
}

void SweepPanel::onRunFinished(int index, const bench::SweepRun& run, const QImage& preview) {
    if (index < 0 || std::size_t(index) >= partialRuns_.size())
        return;
    partialRuns_[std::size_t(index)] = run;
    previews_[std::size_t(index)] = preview;
    rebuildChart();
}

void SweepPanel::onFinished(std::shared_ptr<const bench::SavedSweep> sweep) {
    sweep_ = std::move(sweep);
    runningCombinations_.clear();
    partialRuns_.clear();
    previews_.clear();
    for (const scene::Image8& p : sweep_->previews)
        previews_.push_back(toQImage(p));
    referencePreview_ = toQImage(sweep_->referencePreview);
    run_->setEnabled(true);
    stop_->setEnabled(false);
    emit timingChanged(false);
    rebuildChart();
    const QString path = document_->path();
    if (!path.isEmpty())
        saveBesideProject(path);
    status_->setText(tr("%1 settings measured against a %2 spp reference (its own noise: MARE %3)%4")
                         .arg(sweep_->runs.size())
                         .arg(sweep_->referenceSpp)
                         .arg(percent(sweep_->referenceNoiseMare))
                         .arg(path.isEmpty() ? tr("; saved with the project when it is saved") : QString()));
    emit sweepFinished();
}

void SweepPanel::onFailed(const QString& message, bool cancelled) {
    run_->setEnabled(true);
    stop_->setEnabled(false);
    emit timingChanged(false);
    status_->setText(message);
    emit logMessage(tr("Sweep: %1").arg(message), !cancelled);
    emit sweepFinished();
}

void SweepPanel::onDocumentChanged(bool newProject) {
    if (newProject) {
        job_.cancel();
        sweep_.reset();
        selected_ = -1;
        loadBesideProject();
    }
    rebuildChart(); // the current setting's mark follows the parameters
}

void SweepPanel::saveBesideProject(const QString& projectPath) {
    if (!sweep_)
        return;
    const auto file = bench::savedSweepFileOf(projectPath.toStdString());
    if (auto ok = bench::saveSweep(*sweep_, file); !ok)
        emit logMessage(tr("The sweep was not saved: %1").arg(QString::fromStdString(ok.error().describe())), true);
}

void SweepPanel::loadBesideProject() {
    previews_.clear();
    referencePreview_ = QImage();
    const QString path = document_->path();
    if (path.isEmpty())
        return rebuildChart();
    const auto file = bench::savedSweepFileOf(path.toStdString());
    std::error_code ec;
    if (!std::filesystem::exists(file, ec))
        return rebuildChart();
    auto loaded = bench::loadSweep(file);
    if (!loaded) {
        emit logMessage(tr("The project's saved sweep was not read: %1")
                            .arg(QString::fromStdString(loaded.error().describe())),
                        true);
        return rebuildChart();
    }
    sweep_ = std::make_shared<const bench::SavedSweep>(std::move(*loaded));
    for (const scene::Image8& p : sweep_->previews)
        previews_.push_back(toQImage(p));
    referencePreview_ = toQImage(sweep_->referencePreview);
    status_->setText(tr("Sweep of %1 (%2 settings, %3)")
                         .arg(QString::fromStdString(sweep_->createdAt))
                         .arg(sweep_->runs.size())
                         .arg(QString::fromStdString(sweep_->machine)));
    rebuildChart();
}

std::vector<bool> SweepPanel::front() const {
    if (!sweep_)
        return {};
    std::vector<std::pair<double, double>> points;
    for (const bench::SweepRun& r : sweep_->runs)
        points.emplace_back(r.totalMs, r.indirect.mare);
    return bench::paretoFront(points);
}

std::vector<int> SweepPanel::currentRuns() const {
    std::vector<int> out;
    if (!sweep_)
        return out;
    for (std::size_t i = 0; i < sweep_->runs.size(); ++i)
        if (bench::sameValues(bench::runParameters(sweep_->base, sweep_->runs[i]), document_->parameters()))
            out.push_back(int(i));
    return out;
}

void SweepPanel::rebuildChart() {
    for (QXYSeries* s : std::initializer_list<QXYSeries*>{allPoints_, frontPoints_, frontLine_, currentPoints_,
                                                           selectedPoint_, noiseLine_})
        s->clear();
    // The points shown: the finished sweep's, or those of the one running.
    std::vector<const bench::SweepRun*> runs;
    if (sweep_)
        for (const bench::SweepRun& r : sweep_->runs)
            runs.push_back(&r);
    else
        for (const auto& r : partialRuns_)
            runs.push_back(r ? &*r : nullptr);
    double xMax = 1.0, yMax = 1.0;
    std::vector<std::pair<double, double>> points;
    std::vector<int> shown;
    for (std::size_t i = 0; i < runs.size(); ++i)
        if (runs[i]) {
            points.emplace_back(runs[i]->totalMs, runs[i]->indirect.mare);
            shown.push_back(int(i));
        }
    const std::vector<bool> onFront = bench::paretoFront(points);
    std::vector<std::pair<double, double>> frontXY;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const QPointF p(points[k].first, 100.0 * points[k].second);
        xMax = std::max(xMax, p.x());
        yMax = std::max(yMax, p.y());
        (onFront[k] ? frontPoints_ : allPoints_)->append(p);
        if (onFront[k])
            frontXY.emplace_back(p.x(), p.y());
    }
    std::ranges::sort(frontXY);
    for (const auto& [x, y] : frontXY)
        frontLine_->append(x, y);
    for (int i : currentRuns())
        currentPoints_->append(sweep_->runs[std::size_t(i)].totalMs, 100.0 * sweep_->runs[std::size_t(i)].indirect.mare);
    if (sweep_ && selected_ >= 0 && std::size_t(selected_) < sweep_->runs.size())
        selectedPoint_->append(sweep_->runs[std::size_t(selected_)].totalMs,
                               100.0 * sweep_->runs[std::size_t(selected_)].indirect.mare);
    if (sweep_ && sweep_->referenceNoiseMare > 0.0) {
        const double noise = 100.0 * sweep_->referenceNoiseMare;
        noiseLine_->append(0.0, noise);
        noiseLine_->append(xMax * 1.08, noise);
        yMax = std::max(yMax, noise);
    }
    axisX_->setRange(0.0, xMax * 1.08);
    axisY_->setRange(0.0, yMax * 1.08);
}

int SweepPanel::runAt(const QPointF& point) const {
    if (!sweep_)
        return -1;
    int best = -1;
    double bestDistance = 0.0;
    for (std::size_t i = 0; i < sweep_->runs.size(); ++i) {
        const double dx = (sweep_->runs[i].totalMs - point.x()) / std::max(axisX_->max(), 1e-9);
        const double dy = (100.0 * sweep_->runs[i].indirect.mare - point.y()) / std::max(axisY_->max(), 1e-9);
        const double d = dx * dx + dy * dy;
        if (best < 0 || d < bestDistance) {
            best = int(i);
            bestDistance = d;
        }
    }
    return bestDistance < 1e-4 ? best : -1;
}

void SweepPanel::showRun(int index) {
    if (!sweep_ || index < 0 || std::size_t(index) >= sweep_->runs.size()) {
        detailText_->setText(tr("Hover a point to see its settings; click it to apply them."));
        detailImage_->clear();
        return;
    }
    const bench::SweepRun& r = sweep_->runs[std::size_t(index)];
    const double ratio = r.indirect.meanReference > 0.0 ? r.indirect.meanTest / r.indirect.meanReference : 0.0;
    detailText_->setText(tr("<b>%1</b><br>%2 ms per frame<br>indirect MARE %3 (reference noise %4)<br>"
                            "indirect mean %5x the reference's<br>image MARE %6, SSIM %7")
                             .arg(labelOf(r.settings).toHtmlEscaped())
                             .arg(r.totalMs, 0, 'f', 1)
                             .arg(percent(r.indirect.mare), percent(r.indirect.noiseMare))
                             .arg(ratio, 0, 'f', 2)
                             .arg(percent(r.image.mare))
                             .arg(r.image.ssim, 0, 'f', 3));
    const QImage run = std::size_t(index) < previews_.size() ? previews_[std::size_t(index)] : QImage();
    if (run.isNull() || referencePreview_.isNull()) {
        detailImage_->clear();
        return;
    }
    // Reference | setting, side by side at most 200 px wide each.
    const QImage a = referencePreview_.scaledToWidth(std::min(200, referencePreview_.width()), Qt::SmoothTransformation);
    const QImage b = run.scaled(a.size(), Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    QImage both(a.width() * 2 + 4, a.height(), QImage::Format_RGB32);
    both.fill(Qt::white);
    QPainter painter(&both);
    painter.drawImage(0, 0, a);
    painter.drawImage(a.width() + 4, 0, b);
    painter.end();
    detailImage_->setPixmap(QPixmap::fromImage(both));
}

void SweepPanel::applyRun(int index) {
    if (!sweep_ || index < 0 || std::size_t(index) >= sweep_->runs.size())
        return;
    const bench::SweepRun& r = sweep_->runs[std::size_t(index)];
    // Exactly what was measured: the sweep's base with the run's settings.
    const scene::ParameterSet values = bench::runParameters(sweep_->base, r);
    document_->setAllParameters(values, tr("Apply sweep setting %1").arg(labelOf(r.settings)));
    selected_ = index;
    rebuildChart();
}

int SweepPanel::selectCheapestWithin(double maxErrorPercent) {
    if (!sweep_) {
        status_->setText(tr("Run a sweep first"));
        return -1;
    }
    std::vector<std::pair<double, double>> points;
    for (const bench::SweepRun& r : sweep_->runs)
        points.emplace_back(r.totalMs, 100.0 * r.indirect.mare);
    const auto best = bench::cheapestWithin(points, maxErrorPercent);
    selected_ = best ? int(*best) : -1;
    rebuildChart();
    showRun(selected_);
    if (!best)
        detailText_->setText(tr("No setting of this sweep reaches %1% indirect MARE.").arg(maxErrorPercent));
    return selected_;
}

} // namespace lpv::editor
