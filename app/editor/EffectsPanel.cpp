#include "EffectsPanel.h"

#include <algorithm>

#include "Viewport.h"

#include <QComboBox>
#include <QShowEvent>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace lpv::editor {

EffectsPanel::EffectsPanel(Document* document, Viewport* viewport, QWidget* parent)
    : QWidget(parent), document_(document), viewport_(viewport), table_(new QTableWidget(this)),
      note_(new QLabel(this)), traitsLabel_(new QLabel(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    table_->setColumnCount(4);
    table_->setHorizontalHeaderLabels({tr("Effect"), tr("Setting"), tr("Runs"), tr("Why")});
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->verticalHeader()->hide();
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setWordWrap(true);
    // The "why" column takes the rest of the width and wraps; rows grow to
    // its wrapped text whenever the column's width changes (they were sized
    // once, before the column had its final width, and cut the text off).
    connect(table_->horizontalHeader(), &QHeaderView::sectionResized, table_,
            [this] { table_->resizeRowsToContents(); });
    layout->addWidget(table_);
    traitsLabel_->setWordWrap(true);
    layout->addWidget(traitsLabel_);
    note_->setWordWrap(true);
    note_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    note_->setObjectName("rendererNote");
    layout->addWidget(note_);

    analyseLater_.setSingleShot(true);
    analyseLater_.setInterval(250);
    connect(&analyseLater_, &QTimer::timeout, this, &EffectsPanel::reanalyse);
    connect(document_, &Document::changed, this, [this](Changes c) {
        if (c & (Change::Structure | Change::Geometry | Change::Transforms | Change::Materials | Change::Lights |
                 Change::Sky))
            analyseLater_.start();
        else if (c & Change::Parameters)
            redecide();
    });
    // Sun rays depend on where the camera looks.
    connect(viewport_, &Viewport::viewCameraChanged, this, &EffectsPanel::redecide);
    reanalyse();
}

void EffectsPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    redecide();
}

void EffectsPanel::setRendererNote(const QString& note) { note_->setText(tr("Renderer, last frame: ") + note); }

void EffectsPanel::reanalyse() {
    traits_ = renderer::analyseSceneTraits(document_->scene());
    traitsLabel_->setText(tr("Scene: %1; %2% of %3 probe columns open to the sky; %4 translucent, %5 glossy material")
                              .arg(traits_.hasDirectionalLight ? tr("directional light") : tr("no directional light"))
                              .arg(int(std::lround(100.0f * traits_.openSkyFraction)))
                              .arg(traits_.skyProbes)
                              .arg(traits_.hasTranslucentMaterial ? tr("a") : tr("no"))
                              .arg(traits_.hasGlossyMaterial ? tr("a") : tr("no")));
    redecide();
}

void EffectsPanel::redecide() {
    if (!isVisible() && !decisions_.empty())
        return; // costs nothing while the dock is closed; refreshed when shown
    const scene::Camera camera = viewport_->viewCamera();
    const float aspect = float(std::max(viewport_->width(), 1)) / float(std::max(viewport_->height(), 1));
    decisions_ = renderer::decideEffects(document_->scene(), traits_, document_->parameters(), &camera, aspect);
    updating_ = true;
    table_->setRowCount(int(decisions_.size()));
    const auto& registry = scene::ParameterRegistry::instance();
    for (int row = 0; row < int(decisions_.size()); ++row) {
        const renderer::EffectDecision& d = decisions_[std::size_t(row)];
        table_->setItem(row, 0, new QTableWidgetItem(QString::fromStdString(d.effect)));
        const scene::ParameterInfo* info = registry.find(d.parameter);
        if (info && info->type == scene::ParameterType::Enum) {
            auto* combo = new QComboBox;
            for (const std::string& v : info->enumValues)
                combo->addItem(QString::fromStdString(v));
            combo->setCurrentText(QString::fromStdString(d.setting));
            combo->setToolTip(QString::fromStdString(d.parameter + ": " + info->description));
            const std::string key = d.parameter;
            connect(combo, &QComboBox::currentTextChanged, this, [this, key](const QString& value) {
                if (!updating_)
                    document_->setParameter(key, scene::ParameterValue(value.toStdString()));
            });
            table_->setCellWidget(row, 1, combo);
        } else {
            table_->removeCellWidget(row, 1);
            table_->setItem(row, 1, new QTableWidgetItem(QString::fromStdString(d.parameter + " = " + d.setting)));
        }
        auto* runs = new QTableWidgetItem(d.runs() ? tr("yes") : d.wanted ? tr("wanted") : tr("no"));
        runs->setForeground(d.runs() ? QColor(60, 170, 60) : d.wanted ? QColor(200, 140, 30) : QColor(150, 150, 150));
        table_->setItem(row, 2, runs);
        auto* why = new QTableWidgetItem(QString::fromStdString(d.reason));
        why->setToolTip(why->text());
        table_->setItem(row, 3, why);
    }
    for (int column = 0; column < 3; ++column) // not "why": its one-line width would push it off the panel
        table_->resizeColumnToContents(column);
    // Long effect names wrap rather than leave "why" (the stretched last
    // column) less than its minimum in a dock of the default 400 px.
    table_->setColumnWidth(0, std::min(table_->columnWidth(0), 120));
    table_->resizeRowsToContents();
    updating_ = false;
}

} // namespace lpv::editor
