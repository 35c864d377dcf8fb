#include "LogPanel.h"

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace lpv::editor {

LogPanel::LogPanel(EventLog* log, QWidget* parent) : QWidget(parent), log_(log) {
    setObjectName("logPanel");
    filter_ = new QComboBox(this);
    filter_->addItems({tr("Everything"), tr("Warnings and errors"), tr("Errors")});
    auto* clear = new QPushButton(tr("Clear"), this);
    auto* copy = new QPushButton(tr("Copy"), this);
    copy->setToolTip(tr("Copy the shown messages as text, one per line"));
    table_ = new QTableWidget(0, 4, this);
    table_->setHorizontalHeaderLabels({tr("Time"), tr("Severity"), tr("Source"), tr("Message")});
    table_->verticalHeader()->hide();
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setWordWrap(true);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setSectionResizeMode(3, QHeaderView::Stretch);
    auto* bar = new QHBoxLayout;
    bar->addWidget(filter_);
    bar->addStretch();
    bar->addWidget(copy);
    bar->addWidget(clear);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(bar);
    layout->addWidget(table_);

    connect(filter_, &QComboBox::currentIndexChanged, this, [this] { rebuild(); });
    connect(clear, &QPushButton::clicked, log_, &EventLog::clear);
    connect(copy, &QPushButton::clicked, this, &LogPanel::copyAll);
    connect(log_, &EventLog::added, this, &LogPanel::append);
    connect(log_, &EventLog::cleared, this, &LogPanel::rebuild);
    rebuild();
}

void LogPanel::setMinimumSeverity(int index) {
    filter_->setCurrentIndex(index);
}

bool LogPanel::shown(const EventLog::Entry& entry) const {
    return int(entry.severity) >= filter_->currentIndex();
}

void LogPanel::append(const EventLog::Entry& entry) {
    if (!shown(entry))
        return;
    const int row = table_->rowCount();
    table_->insertRow(row);
    const QStringList cells{entry.time.toString("HH:mm:ss.zzz"), EventLog::toString(entry.severity),
                            entry.source, entry.text};
    for (int c = 0; c < cells.size(); ++c) {
        auto* item = new QTableWidgetItem(cells[c]);
        if (entry.severity == EventLog::Severity::Error)
            item->setForeground(QColor(200, 40, 40));
        else if (entry.severity == EventLog::Severity::Warning)
            item->setForeground(QColor(170, 110, 0));
        table_->setItem(row, c, item);
    }
    table_->item(row, 0)->setToolTip(entry.time.toString(Qt::ISODateWithMs));
    table_->scrollToBottom();
}

void LogPanel::rebuild() {
    table_->setRowCount(0);
    for (const EventLog::Entry& e : log_->entries())
        append(e);
}

void LogPanel::copyAll() const {
    QStringList lines;
    for (int r = 0; r < table_->rowCount(); ++r) {
        QStringList cells;
        for (int c = 0; c < table_->columnCount(); ++c)
            cells << table_->item(r, c)->text();
        lines << cells.join("  ");
    }
    QApplication::clipboard()->setText(lines.join("\n"));
}

} // namespace lpv::editor
