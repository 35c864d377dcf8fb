#pragma once
// The Log dock: the EventLog as a table (time, severity, source, message),
// filtered by severity, newest at the bottom, with Clear and Copy.
#include "EventLog.h"

#include <QWidget>

class QComboBox;
class QTableWidget;

namespace lpv::editor {

class LogPanel : public QWidget {
    Q_OBJECT
  public:
    explicit LogPanel(EventLog* log, QWidget* parent = nullptr);

    QTableWidget* table() const { return table_; }
    // 0: everything, 1: warnings and errors, 2: errors.
    void setMinimumSeverity(int index);

  private:
    void append(const EventLog::Entry& entry);
    void rebuild();
    bool shown(const EventLog::Entry& entry) const;
    void copyAll() const;

    EventLog* log_;
    QComboBox* filter_ = nullptr;
    QTableWidget* table_ = nullptr;
};

} // namespace lpv::editor
