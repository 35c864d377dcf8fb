#include "SweepPanel.h"

#include "Document.h"

#include "lpv/bench/Pareto.h"
#include "lpv/bench/Plots.h"
#include "lpv/bench/Questions.h"
#include "lpv/bench/SweepOutput.h"
#include "lpv/renderer/GpuMemory.h"

#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLegendMarker>
#include <QLineSeries>
#include <QMouseEvent>
#include <QPainter>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QStyle>
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
enum RunColumn { kRunSetting, kRunTime, kRunSame, kRunMemory, kRunError, kRunMean, kRunColumns };

const QColor kBiasedColor(235, 140, 20);
const QColor kPointColor(40, 110, 180);
const QColor kFrontColor(200, 60, 40);
constexpr double kMiB = 1024.0 * 1024.0;
// The hovered run's preview beside the reference's: each at most this wide,
// and the detail column exactly as wide as the two.
constexpr int kPreviewWidth = 160;
constexpr int kPreviewGap = 4;

QString biasedName() {
    return QObject::tr("biased (mean outside 0.8-1.25x)");
}

QString percent(double v) {
    return QString::number(100.0 * v, 'f', 1) + "%";
}

QString labelOf(const std::vector<bench::Setting>& settings) {
    return settings.empty() ? QObject::tr("current settings") : QString::fromStdString(bench::sweepLabel(settings));
}

// "12.30 ms ±0.40 over 5 rounds" (± half the interquartile range), or the single time of an older sweep.
QString timeText(const bench::SweepRun& r) {
    if (r.total.rounds <= 0)
        return QObject::tr("%1 ms (one sample)").arg(r.totalMs, 0, 'f', 2);
    if (r.total.rounds == 1)
        return QObject::tr("%1 ms (1 round)").arg(r.total.median, 0, 'f', 2);
    return QObject::tr("%1 ms ±%2 over %3 rounds")
        .arg(r.total.median, 0, 'f', 2)
        .arg(0.5 * r.total.spread(), 0, 'f', 2)
        .arg(r.total.rounds);
}

QString memoryText(const bench::SweepRun& r) {
    return r.gpuBytes ? QString::fromStdString(renderer::formatBytes(r.gpuBytes)) : QStringLiteral("-");
}

bool biased(const bench::SweepRun& r) {
    return bench::biasedMean(bench::meanRatio(r.indirect));
}

double axisCostMs(const bench::SweepRun& r) {
    return r.total.rounds > 0 ? r.total.median : r.totalMs;
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
    setQuestionRows(defaultQuestionRows());
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

    // Middle: the plot (log cost against the symmetric error) over the runs' table.
    auto* middle = new QWidget(split);
    auto* middleLayout = new QVBoxLayout(middle);
    middleLayout->setContentsMargins(0, 0, 0, 0);
    auto* axisRow = new QHBoxLayout();
    axisRow->addWidget(new QLabel(tr("Cost"), middle));
    axisChoice_ = new QComboBox(middle);
    axisChoice_->setObjectName("sweepAxis");
    axisChoice_->addItem(tr("GPU time (ms)"));
    axisChoice_->addItem(tr("GPU memory (MiB)"));
    axisChoice_->setToolTip(
        tr("The chart's x axis, its Pareto front and \"Cheapest within\": the frame's GPU time "
           "(median over interleaved rounds, the bar its interquartile range) or the GPU "
           "memory of the resources the frame allocated (frame graph and LPV volumes)"));
    connect(axisChoice_, &QComboBox::currentIndexChanged, this, [this] {
        rebuildChart();
        showRun(selected_);
    });
    axisRow->addWidget(axisChoice_);
    axisRow->addStretch(1);
    middleLayout->addLayout(axisRow);
    chart_ = new QChart();
    chart_->setAnimationOptions(QChart::NoAnimation);
    // A log axis with round ticks: QCategoryAxis labels placed on log10 of 1, 2, 5 x 10^k
    // (QLogValueAxis labels powers of ten only, none inside a range such as 2..8 ms).
    axisX_ = new QCategoryAxis(chart_);
    axisX_->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
    axisY_ = new QValueAxis(chart_);
    axisY_->setTitleText(tr("indirect error % (symmetric)"));
    axisY_->setLabelFormat("%.0f");
    chart_->addAxis(axisX_, Qt::AlignBottom);
    chart_->addAxis(axisY_, Qt::AlignLeft);
    // Beside the plot, one entry a line: along the top the names were cut short.
    chart_->legend()->setAlignment(Qt::AlignRight);
    QFont legendFont = chart_->legend()->font();
    legendFont.setPointSizeF(legendFont.pointSizeF() * 0.85);
    chart_->legend()->setFont(legendFont);
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
    frontLine_->setPen(QPen(kFrontColor, 1.5));
    addSeries(frontLine_, tr("Pareto front"));
    allPoints_ = new QScatterSeries(chart_);
    allPoints_->setMarkerSize(8);
    allPoints_->setColor(kPointColor);
    addSeries(allPoints_, tr("settings"));
    frontPoints_ = new QScatterSeries(chart_);
    frontPoints_->setMarkerSize(10);
    frontPoints_->setColor(kFrontColor);
    addSeries(frontPoints_, tr("on the front"));
    biasedPoints_ = new QScatterSeries(chart_);
    biasedPoints_->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
    biasedPoints_->setMarkerSize(9);
    biasedPoints_->setColor(kBiasedColor);
    addSeries(biasedPoints_, biasedName());
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
    chartView_ = new QChartView(chart_, middle);
    chartView_->setRenderHint(QPainter::Antialiasing);
    chartView_->setMinimumWidth(320);
    chartView_->setMinimumHeight(240);
    // Hover and click are read from the view, not from each series: the
    // point nearest the cursor within a few pixels, whichever item (a
    // quartile bar, the front's line, the current star) lies on top of it.
    // A series' own click went to the topmost item, often a bar, and was lost.
    chartView_->viewport()->setMouseTracking(true);
    chartView_->viewport()->installEventFilter(this);
    middleLayout->addWidget(chartView_, 3);
    runsTable_ = new QTableWidget(0, kRunColumns, middle);
    runsTable_->setObjectName("sweepRuns");
    runsTable_->setHorizontalHeaderLabels(
        {tr("Setting"), tr("GPU time"), tr("Same cost as"), tr("GPU memory"), tr("Error"), tr("Mean")});
    runsTable_->horizontalHeaderItem(kRunTime)->setToolTip(
        tr("GPU ms per frame: the median over the interleaved timing rounds ± half the interquartile "
           "range (the rounds, min and max on each cell's tip)"));
    runsTable_->horizontalHeaderItem(kRunSame)->setToolTip(
        tr("Runs (by row) whose time is the same within the noise"));
    runsTable_->horizontalHeaderItem(kRunError)->setToolTip(
        tr("Indirect light's symmetric error: exp(mean |ln((t+e)/(r+e))|) - 1, too dark and too "
           "bright alike"));
    runsTable_->horizontalHeaderItem(kRunMean)->setToolTip(
        tr("The indirect light's mean over the reference's; outside 0.8-1.25x it is biased"));
    runsTable_->verticalHeader()->setDefaultSectionSize(20);
    runsTable_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    runsTable_->setSelectionBehavior(QAbstractItemView::SelectRows);
    runsTable_->setSelectionMode(QAbstractItemView::SingleSelection);
    runsTable_->horizontalHeader()->setSectionResizeMode(kRunSetting, QHeaderView::Stretch);
    connect(runsTable_, &QTableWidget::cellClicked, this, [this](int row, int) {
        if (!sweep_)
            return;
        selected_ = row;
        rebuildChart();
        showRun(row);
    });
    middleLayout->addWidget(runsTable_, 2);

    // Right: the hovered or selected point, in a column of fixed width whose
    // content scrolls. What a hover shows (text, previews) never resizes it:
    // a column that grew on hover shrank the chart, the point moved from
    // under the cursor, and a click without moving applied nothing (issue #46).
    auto* detailScroll = new QScrollArea(split);
    detailScroll->setObjectName("sweepDetail");
    detailScroll->setFrameShape(QFrame::NoFrame);
    detailScroll->setWidgetResizable(true);
    detailScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    detailScroll->setFixedWidth(2 * kPreviewWidth + kPreviewGap +
                                detailScroll->style()->pixelMetric(QStyle::PM_ScrollBarExtent) + 2);
    auto* detail = new QWidget(detailScroll);
    detailScroll->setWidget(detail);
    auto* detailLayout = new QVBoxLayout(detail);
    detailLayout->setContentsMargins(0, 0, 0, 0);
    auto* cheapest = new QHBoxLayout();
    maxError_ = new QDoubleSpinBox(detail);
    maxError_->setRange(0.1, 100000.0);
    maxError_->setValue(10.0);
    maxError_->setSuffix(" %");
    maxError_->setToolTip(tr("Bound on the indirect light's symmetric error"));
    auto* pick = new QPushButton(tr("Cheapest within"), detail);
    pick->setToolTip(
        tr("Select the cheapest setting (on the chart's axis) whose indirect symmetric error is at "
           "most this; biased settings (mean outside 0.8-1.25x) are passed over"));
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
    rebuildChart();

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

std::vector<bench::SweepQuestionRow> SweepPanel::defaultQuestionRows() {
    std::vector<bench::SweepQuestionRow> rows;
    for (const bench::Question& q : bench::reportQuestions())
        rows.push_back(
            {q.name, q.sweep, std::ranges::find(kDefaultQuestions, q.name) != std::end(kDefaultQuestions)});
    return rows;
}

std::vector<bench::SweepQuestionRow> SweepPanel::questionRows() const {
    std::vector<bench::SweepQuestionRow> rows;
    for (int row = 0; row < questions_->rowCount(); ++row) {
        const QTableWidgetItem* name = questions_->item(row, kQuestion);
        const QTableWidgetItem* values = questions_->item(row, kValues);
        if (name)
            rows.push_back({name->text().toStdString(), values ? values->text().toStdString() : std::string(),
                            name->checkState() == Qt::Checked});
    }
    return rows;
}

void SweepPanel::setQuestionRows(const std::vector<bench::SweepQuestionRow>& rows) {
    const auto questions = bench::reportQuestions();
    questions_->setRowCount(0);
    for (const bench::SweepQuestionRow& q : rows) {
        const int row = questions_->rowCount();
        questions_->insertRow(row);
        auto* name = new QTableWidgetItem(QString::fromStdString(q.name));
        // The report's questions keep their names; a row the user added can be renamed.
        if (std::ranges::any_of(questions, [&](const bench::Question& r) { return r.name == q.name; }))
            name->setFlags(name->flags() & ~Qt::ItemIsEditable);
        name->setCheckState(q.checked ? Qt::Checked : Qt::Unchecked);
        questions_->setItem(row, kQuestion, name);
        questions_->setItem(row, kValues, new QTableWidgetItem(QString::fromStdString(q.values)));
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

void SweepPanel::onFinished(std::shared_ptr<const bench::SavedSweep> sweep, const QString& timing) {
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
    // One pass over the text: the timing note holds "%" signs of its own.
    status_->setText(
        tr("%1 settings measured against a %2 spp reference (its own noise: %3 symmetric error); "
           "%4%5")
            .arg(QString::number(sweep_->runs.size()), QString::number(sweep_->referenceSpp),
                 percent(sweep_->runs.empty() ? 0.0 : sweep_->runs.front().indirect.noiseSymmetricError()),
                 timing, path.isEmpty() ? tr("; saved with the project when it is saved") : QString()));
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
    // The rows as they are now, so that the project reopens asking the same questions.
    bench::SavedSweep saved = *sweep_;
    saved.questions = questionRows();
    if (auto ok = bench::saveSweep(saved, file); !ok)
        emit logMessage(tr("The sweep was not saved: %1").arg(QString::fromStdString(ok.error().describe())), true);
}

void SweepPanel::loadBesideProject() {
    previews_.clear();
    referencePreview_ = QImage();
    // A project asks the default questions unless its saved sweep kept its own.
    setQuestionRows(defaultQuestionRows());
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
    if (!sweep_->questions.empty()) // none in a sweep saved before issue #46
        setQuestionRows(sweep_->questions);
    for (const scene::Image8& p : sweep_->previews)
        previews_.push_back(toQImage(p));
    referencePreview_ = toQImage(sweep_->referencePreview);
    status_->setText(tr("Sweep of %1 (%2 settings, %3)")
                         .arg(QString::fromStdString(sweep_->createdAt))
                         .arg(sweep_->runs.size())
                         .arg(QString::fromStdString(sweep_->machine)));
    rebuildChart();
}

std::vector<const bench::SweepRun*> SweepPanel::shownRuns() const {
    std::vector<const bench::SweepRun*> runs;
    if (sweep_)
        for (const bench::SweepRun& r : sweep_->runs)
            runs.push_back(&r);
    else
        for (const auto& r : partialRuns_)
            runs.push_back(r ? &*r : nullptr);
    return runs;
}

SweepPanel::CostAxis SweepPanel::costAxis() const {
    return axisChoice_->currentIndex() == 1 ? CostAxis::Memory : CostAxis::Time;
}

void SweepPanel::setCostAxis(CostAxis axis) {
    axisChoice_->setCurrentIndex(axis == CostAxis::Memory ? 1 : 0);
}

double SweepPanel::axisCost(const bench::SweepRun& r) const {
    if (costAxis() == CostAxis::Memory)
        return double(r.gpuBytes) / kMiB;
    return r.total.rounds > 0 ? r.total.median : r.totalMs;
}

double SweepPanel::costOf(int index) const {
    const auto runs = shownRuns();
    if (index < 0 || std::size_t(index) >= runs.size() || !runs[std::size_t(index)])
        return 0.0;
    return axisCost(*runs[std::size_t(index)]);
}

std::optional<QPointF> SweepPanel::plottedPoint(int index) const {
    if (index < 0 || std::size_t(index) >= plotted_.size())
        return std::nullopt;
    return plotted_[std::size_t(index)];
}

bench::CostPoint SweepPanel::costPoint(const bench::SweepRun& r) const {
    return costAxis() == CostAxis::Memory ? bench::memoryErrorPoint(r) : bench::timeErrorPoint(r);
}

namespace {

// The front among the runs with a cost on this axis (a sweep saved before
// memory was counted has none); the others are not on it.
template <typename CostPointOf, typename CostOf>
std::vector<bool> frontOf(const std::vector<const bench::SweepRun*>& runs, bool memory, CostPointOf point,
                          CostOf cost) {
    std::vector<bench::CostPoint> points;
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < runs.size(); ++i)
        if (runs[i] && cost(*runs[i]) > 0.0) {
            points.push_back(point(*runs[i]));
            index.push_back(i);
        }
    const std::vector<bool> front = bench::paretoFront(points, memory ? 0.0 : bench::kSameCostFraction);
    std::vector<bool> out(runs.size(), false);
    for (std::size_t k = 0; k < index.size(); ++k)
        out[index[k]] = front[k];
    return out;
}

} // namespace

std::vector<bool> SweepPanel::front() const {
    if (!sweep_)
        return {};
    return frontOf(
        shownRuns(), costAxis() == CostAxis::Memory,
        [this](const bench::SweepRun& r) { return costPoint(r); },
        [this](const bench::SweepRun& r) { return axisCost(r); });
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
    for (QXYSeries* s : std::initializer_list<QXYSeries*>{allPoints_, frontPoints_, biasedPoints_, frontLine_,
                                                          currentPoints_, selectedPoint_, noiseLine_})
        s->clear();
    for (QLineSeries* bar : spreadBars_) {
        chart_->removeSeries(bar);
        delete bar;
    }
    spreadBars_.clear();

    const std::vector<const bench::SweepRun*> runs = shownRuns();
    const bool memory = costAxis() == CostAxis::Memory;
    const std::vector<bool> onFront = frontOf(
        runs, memory, [this](const bench::SweepRun& r) { return costPoint(r); },
        [this](const bench::SweepRun& r) { return axisCost(r); });
    plotted_.assign(runs.size(), std::nullopt);
    double lo = 0.0, hi = 0.0, yMax = 1.0;
    std::vector<QPointF> frontXY;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        if (!runs[i])
            continue;
        const bench::SweepRun& r = *runs[i];
        const double cost = axisCost(r);
        if (!(cost > 0.0))
            continue; // not measured on this axis (memory in an older sweep)
        const double error = 100.0 * r.indirect.symmetricError();
        const QPointF p(std::log10(cost), error);
        plotted_[i] = p;
        double low = cost, high = cost;
        const bool bar = !memory && r.total.rounds > 1 && r.total.q3 > r.total.q1 && r.total.q1 > 0.0;
        if (bar) {
            low = std::min(low, r.total.q1);
            high = std::max(high, r.total.q3);
        }
        lo = lo > 0.0 ? std::min(lo, low) : low;
        hi = std::max(hi, high);
        yMax = std::max(yMax, error);
        const bool isBiased = biased(r);
        (isBiased ? biasedPoints_ : onFront[i] ? frontPoints_ : allPoints_)->append(p);
        if (onFront[i])
            frontXY.push_back(p);
        if (bar) {
            // The time's interquartile range over the rounds, as a bar through the point.
            auto* line = new QLineSeries(chart_);
            line->setName(tr("time spread (quartiles over rounds)"));
            line->setPen(QPen(isBiased ? kBiasedColor : onFront[i] ? kFrontColor : kPointColor, 1.5));
            line->append(std::log10(r.total.q1), error);
            line->append(std::log10(r.total.q3), error);
            chart_->addSeries(line);
            line->attachAxis(axisX_);
            line->attachAxis(axisY_);
            const bool firstBar = spreadBars_.empty();
            for (QLegendMarker* m : chart_->legend()->markers(line))
                m->setVisible(firstBar);
            spreadBars_.push_back(line);
        }
    }
    std::ranges::sort(frontXY, [](const QPointF& a, const QPointF& b) { return a.x() < b.x(); });
    for (const QPointF& p : frontXY)
        frontLine_->append(p);
    for (int i : currentRuns())
        if (plotted_[std::size_t(i)])
            currentPoints_->append(*plotted_[std::size_t(i)]);
    if (selected_ >= 0 && std::size_t(selected_) < plotted_.size() && plotted_[std::size_t(selected_)])
        selectedPoint_->append(*plotted_[std::size_t(selected_)]);

    // The x range: the points with a margin, wide enough for two round ticks.
    if (!(lo > 0.0)) {
        lo = memory ? 1.0 : 1.0;
        hi = 10.0;
    }
    double x0 = lo / 1.15, x1 = hi * 1.15;
    const std::vector<double> ticks = bench::logTicks(x0, x1);
    auto inside = [&] { return std::ranges::count_if(ticks, [&](double t) { return t >= x0 && t <= x1; }); };
    if (inside() < 2) {
        for (double t : ticks) { // the round ticks just around the range
            if (t < x0)
                lo = t;
            if (t > x1 && hi < t) {
                hi = t;
                break;
            }
        }
        x0 = std::min(x0, lo);
        x1 = std::max(x1, hi);
    }
    for (const QString& label : axisX_->categoriesLabels())
        axisX_->remove(label);
    axisX_->setStartValue(std::log10(x0));
    for (double t : ticks)
        if (t >= x0 && t <= x1)
            axisX_->append(QString::fromStdString(bench::tickLabel(t)), std::log10(t));
    axisX_->setRange(std::log10(x0), std::log10(x1));
    axisX_->setTitleText(memory ? tr("GPU memory, MiB (log scale)") : tr("GPU ms per frame (log scale)"));
    chart_->setTitle(memory ? tr("Indirect light error against GPU memory")
                            : tr("Indirect light error against GPU time"));

    const bench::SweepRun* first = runs.empty() ? nullptr : runs.front();
    if (first && first->indirect.noiseLogError > 0.0) {
        const double noise = 100.0 * first->indirect.noiseSymmetricError();
        noiseLine_->append(std::log10(x0), noise);
        noiseLine_->append(std::log10(x1), noise);
        yMax = std::max(yMax, noise);
    }
    axisY_->setRange(0.0, yMax * 1.08);
    axisY_->applyNiceNumbers(); // ticks at 0, 50, 100 %, not at 70.2
    rebuildRunsTable(runs, onFront);
}

void SweepPanel::rebuildRunsTable(const std::vector<const bench::SweepRun*>& runs,
                                  const std::vector<bool>& onFront) {
    const QSignalBlocker block(runsTable_);
    runsTable_->setRowCount(int(runs.size()));
    auto cell = [this](int row, int column, const QString& text, const QString& tip = {}) {
        auto* item = new QTableWidgetItem(text);
        if (!tip.isEmpty())
            item->setToolTip(tip);
        runsTable_->setItem(row, column, item);
        return item;
    };
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const int row = int(i);
        const bench::SweepRun* r = runs[i];
        const std::vector<bench::Setting>& settings = r ? r->settings
                                                      : i < runningCombinations_.size()
                                                          ? runningCombinations_[i]
                                                          : std::vector<bench::Setting>{};
        QTableWidgetItem* name = cell(row, kRunSetting, labelOf(settings));
        if (!r) {
            for (int c = kRunTime; c < kRunColumns; ++c)
                cell(row, c, c == kRunTime ? tr("measuring...") : QStringLiteral("-"));
            continue;
        }
        if (onFront[i])
            name->setToolTip(tr("On the Pareto front of the chart's axis"));
        cell(row, kRunTime,
             r->total.rounds > 1
                 ? tr("%1 ms ±%2").arg(r->total.median, 0, 'f', 2).arg(0.5 * r->total.spread(), 0, 'f', 2)
                 : tr("%1 ms").arg(axisCostMs(*r), 0, 'f', 2),
             r->total.rounds > 0 ? tr("%1; min %2 ms, max %3 ms")
                                       .arg(timeText(*r))
                                       .arg(r->total.min, 0, 'f', 2)
                                       .arg(r->total.max, 0, 'f', 2)
                                 : timeText(*r));
        QStringList same;
        if (r->total.rounds > 0)
            for (std::size_t j = 0; j < runs.size(); ++j)
                if (j != i && runs[j] && runs[j]->total.rounds > 0 &&
                    bench::sameCost(r->total, runs[j]->total))
                    same << QString::number(j + 1);
        cell(row, kRunSame, same.join(", "));
        cell(row, kRunMemory, memoryText(*r),
             r->lpvBytes
                 ? tr("LPV volumes %1").arg(QString::fromStdString(renderer::formatBytes(r->lpvBytes)))
                 : QString());
        cell(row, kRunError,
             percent(r->indirect.symmetricError()) +
                 (r->indirect.symmetricBelowNoise() ? tr(" (below noise)") : QString()),
             tr("reference noise %1; MARE %2")
                 .arg(percent(r->indirect.noiseSymmetricError()), percent(r->indirect.mare)));
        const double ratio = bench::meanRatio(r->indirect);
        QTableWidgetItem* mean =
            cell(row, kRunMean,
                 biased(*r) ? tr("%1x biased").arg(ratio, 0, 'f', 2) : tr("%1x").arg(ratio, 0, 'f', 2));
        if (biased(*r)) {
            mean->setForeground(kBiasedColor.darker(130));
            mean->setToolTip(
                tr("Mean outside 0.8-1.25x the reference's: biased, passed over by \"Cheapest within\""));
        }
    }
    runsTable_->resizeColumnsToContents();
    runsTable_->horizontalHeader()->setSectionResizeMode(kRunSetting, QHeaderView::Stretch);
    if (selected_ >= 0 && selected_ < runsTable_->rowCount())
        runsTable_->selectRow(selected_);
    else
        runsTable_->clearSelection();
}

int SweepPanel::runAtPixel(const QPoint& pos) const {
    if (!sweep_)
        return -1;
    // About a marker's radius, so a click on its edge still counts.
    constexpr double kPickRadius = 7.0;
    int best = -1;
    double bestDistance = kPickRadius * kPickRadius;
    for (std::size_t i = 0; i < plotted_.size(); ++i) {
        if (!plotted_[i])
            continue;
        const QPointF at = chartView_->mapFromScene(chart_->mapToPosition(*plotted_[i], allPoints_));
        const QPointF d = at - QPointF(pos);
        const double distance = d.x() * d.x() + d.y() * d.y();
        if (distance <= bestDistance) {
            best = int(i);
            bestDistance = distance;
        }
    }
    return best;
}

bool SweepPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched != chartView_->viewport())
        return QWidget::eventFilter(watched, event);
    const auto* mouse = dynamic_cast<const QMouseEvent*>(event);
    if (!mouse)
        return QWidget::eventFilter(watched, event);
    const QPoint pos = mouse->position().toPoint();
    if (event->type() == QEvent::MouseMove && mouse->buttons() == Qt::NoButton) {
        if (const int index = runAtPixel(pos); index >= 0)
            showRun(index);
    } else if (event->type() == QEvent::MouseButtonPress && mouse->button() == Qt::LeftButton) {
        pressedRun_ = runAtPixel(pos);
    } else if (event->type() == QEvent::MouseButtonRelease && mouse->button() == Qt::LeftButton) {
        // A click: pressed and released on the same point. Applying rebuilds
        // the series: not inside the view's own mouse event.
        const int index = runAtPixel(pos);
        if (index >= 0 && index == pressedRun_)
            QMetaObject::invokeMethod(
                this, [this, index] { applyRun(index); }, Qt::QueuedConnection);
        pressedRun_ = -1;
    }
    return QWidget::eventFilter(watched, event);
}

void SweepPanel::showSweep(std::shared_ptr<const bench::SavedSweep> sweep) {
    job_.cancel();
    sweep_ = std::move(sweep);
    selected_ = -1;
    runningCombinations_.clear();
    partialRuns_.clear();
    previews_.clear();
    referencePreview_ = QImage();
    if (sweep_) {
        for (const scene::Image8& p : sweep_->previews)
            previews_.push_back(toQImage(p));
        referencePreview_ = toQImage(sweep_->referencePreview);
    }
    rebuildChart();
    showRun(-1);
}

void SweepPanel::showRun(int index) {
    if (!sweep_ || index < 0 || std::size_t(index) >= sweep_->runs.size()) {
        detailText_->setText(tr("Hover a point to see its settings; click it to apply them."));
        detailImage_->clear();
        return;
    }
    const bench::SweepRun& r = sweep_->runs[std::size_t(index)];
    const double ratio = bench::meanRatio(r.indirect);
    QStringList same;
    for (std::size_t j : bench::sameCostAs(sweep_->runs, std::size_t(index)))
        same << labelOf(sweep_->runs[j].settings).toHtmlEscaped();
    QString time = tr("GPU time %1 per frame").arg(timeText(r).toHtmlEscaped());
    if (r.total.rounds > 1)
        time += tr(" (median ± half the interquartile range; %1-%2 ms)")
                    .arg(r.total.min, 0, 'f', 2)
                    .arg(r.total.max, 0, 'f', 2);
    const QString sameText = r.total.rounds == 0 ? QString()
                             : same.isEmpty()
                                 ? tr("no other setting costs the same within the noise")
                                 : tr("the same cost within the noise as %1").arg(same.join(", "));
    const QString memory = r.gpuBytes ? tr("GPU memory %1 (LPV volumes %2)")
                                            .arg(QString::fromStdString(renderer::formatBytes(r.gpuBytes)),
                                                 QString::fromStdString(renderer::formatBytes(r.lpvBytes)))
                                      : tr("GPU memory not measured in this sweep");
    const QString mean =
        biased(r)
            ? tr("<span style=\"color:#c06000\">mean %1x: biased</span> (outside 0.8-1.25x the reference's "
                 "light; \"Cheapest within\" passes it over)")
                  .arg(ratio, 0, 'f', 2)
            : tr("mean %1x the reference's").arg(ratio, 0, 'f', 2);
    QStringList lines{QStringLiteral("<b>%1</b>").arg(labelOf(r.settings).toHtmlEscaped()), time};
    if (!sameText.isEmpty())
        lines << sameText;
    lines << memory
          << tr("indirect error %1 symmetric (reference noise %2)%3")
                 .arg(percent(r.indirect.symmetricError()), percent(r.indirect.noiseSymmetricError()),
                      r.indirect.symmetricBelowNoise() ? tr(", below the noise") : QString())
          << mean
          << tr("indirect MARE %1 (reference noise %2)")
                 .arg(percent(r.indirect.mare), percent(r.indirect.noiseMare))
          << tr("image MARE %1, SSIM %2").arg(percent(r.image.mare)).arg(r.image.ssim, 0, 'f', 3);
    detailText_->setText(lines.join("<br>"));
    const QImage run = std::size_t(index) < previews_.size() ? previews_[std::size_t(index)] : QImage();
    if (run.isNull() || referencePreview_.isNull()) {
        detailImage_->clear();
        return;
    }
    // Reference | setting, side by side, as wide as the detail column holds.
    const QImage a = referencePreview_.scaledToWidth(std::min(kPreviewWidth, referencePreview_.width()),
                                                     Qt::SmoothTransformation);
    const QImage b = run.scaled(a.size(), Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    QImage both(a.width() * 2 + kPreviewGap, a.height(), QImage::Format_RGB32);
    both.fill(Qt::white);
    QPainter painter(&both);
    painter.drawImage(0, 0, a);
    painter.drawImage(a.width() + kPreviewGap, 0, b);
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
    const bool memory = costAxis() == CostAxis::Memory;
    std::vector<bench::CostPoint> points;
    std::vector<std::size_t> index;
    bool biasedReach = false;
    for (std::size_t i = 0; i < sweep_->runs.size(); ++i) {
        const bench::SweepRun& r = sweep_->runs[i];
        if (!(axisCost(r) > 0.0))
            continue;
        points.push_back(costPoint(r));
        index.push_back(i);
        biasedReach = biasedReach || (points.back().biased && 100.0 * points.back().error <= maxErrorPercent);
    }
    const auto best =
        bench::cheapestWithin(points, maxErrorPercent / 100.0, memory ? 0.0 : bench::kSameCostFraction);
    selected_ = best ? int(index[*best]) : -1;
    rebuildChart();
    showRun(selected_);
    if (!best)
        detailText_->setText(
            biasedReach
                ? tr("Only biased settings (mean outside 0.8-1.25x the reference's) reach %1% symmetric "
                     "error; none is chosen.")
                      .arg(maxErrorPercent)
                : tr("No setting of this sweep reaches %1% symmetric error.").arg(maxErrorPercent));
    return selected_;
}

} // namespace lpv::editor
