#include "ParameterInspector.h"

#include <QAbstractSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace lpv::editor {
namespace {

using scene::ParameterInfo;

// The order of issue #7; groups not listed follow alphabetically.
const QStringList kGroupOrder{"LPV", "RSM", "Shadows", "Effects", "Output", "Radiosity", "Reference"};

qsizetype groupRank(const QString& group) {
    const qsizetype i = kGroupOrder.indexOf(group);
    return i >= 0 ? i : kGroupOrder.size();
}

} // namespace

ParameterInspector::ParameterInspector(QWidget* parent, const scene::ParameterRegistry& registry)
    : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);

    search_ = new QLineEdit(this);
    search_->setPlaceholderText(tr("Search parameters (name, key, description)"));
    search_->setClearButtonEnabled(true);
    search_->setObjectName("parameterSearch");
    layout->addWidget(search_);
    connect(search_, &QLineEdit::textChanged, this, &ParameterInspector::setFilter);

    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    layout->addWidget(scroll, 1);

    sectionsContainer_ = new QWidget(scroll);
    auto* sectionsLayout = new QVBoxLayout(sectionsContainer_);
    sectionsLayout->setContentsMargins(0, 0, 0, 0);
    sectionsLayout->setSpacing(2);

    // Sections first, in display order; the registry lists parameters by key.
    std::vector<const ParameterInfo*> params;
    for (const ParameterInfo& info : registry.all())
        params.push_back(&info);
    std::stable_sort(params.begin(), params.end(), [](const ParameterInfo* a, const ParameterInfo* b) {
        const QString ga = QString::fromStdString(a->group);
        const QString gb = QString::fromStdString(b->group);
        const auto ra = groupRank(ga);
        const auto rb = groupRank(gb);
        return ra != rb ? ra < rb : (ra == kGroupOrder.size() && ga < gb);
    });
    for (const ParameterInfo* info : params)
        addEntry(*info);

    alignColumns();

    noMatches_ = new QLabel(tr("No parameter matches the search."), sectionsContainer_);
    noMatches_->setAlignment(Qt::AlignCenter);
    noMatches_->setEnabled(false);
    noMatches_->hide();
    sectionsLayout->addWidget(noMatches_);
    sectionsLayout->addStretch(1);
    scroll->setWidget(sectionsContainer_);

    applyFilter();
}

std::size_t ParameterInspector::sectionFor(const QString& group, QWidget* container) {
    for (std::size_t i = 0; i < sections_.size(); ++i)
        if (sections_[i].name == group)
            return i;
    Section s;
    s.name = group;
    s.header = new QToolButton(container);
    s.header->setObjectName("group:" + group);
    s.header->setCheckable(true);
    s.header->setChecked(true);
    s.header->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    s.header->setArrowType(Qt::DownArrow);
    s.header->setAutoRaise(true);
    s.header->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    QFont bold = s.header->font();
    bold.setBold(true);
    s.header->setFont(bold);
    s.body = new QWidget(container);
    s.form = new QFormLayout(s.body);
    s.form->setContentsMargins(12, 0, 0, 6);
    s.form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    s.form->setLabelAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    container->layout()->addWidget(s.header);
    container->layout()->addWidget(s.body);
    sections_.push_back(s);
    connect(s.header, &QToolButton::toggled, this, [this, group](bool on) { setGroupExpanded(group, on); });
    return sections_.size() - 1;
}

void ParameterInspector::addEntry(const ParameterInfo& info) {
    const QString key = QString::fromStdString(info.key);
    const QString group = QString::fromStdString(info.group);
    Entry e;
    e.info = &info;
    e.section = sectionFor(group, sectionsContainer_);
    Section& section = sections_[e.section];
    e.editor = ParameterEditor::create(info, section.body);
    e.label = new QLabel(parameterLabel(info), section.body);
    e.label->setToolTip(parameterToolTip(info));
    e.label->setBuddy(e.editor->input());
    e.row = section.form->rowCount();
    section.form->addRow(e.label, e.editor);
    ++section.total;
    e.haystack = QStringList{key, parameterLabel(info), QString::fromStdString(info.description), group}
                     .join('\n')
                     .toLower();
    byKey_.insert(key, entries_.size());
    entries_.push_back(e);
    updateLabel(entries_.back());

    ParameterEditor* editor = e.editor;
    connect(editor, &ParameterEditor::edited, this,
            [this, key](const scene::ParameterValue& v) { emit parameterEdited(key, v); });
    connect(editor, &ParameterEditor::resetRequested, this,
            [this, key] { emit parameterResetRequested(key); });
    connect(editor, &ParameterEditor::valueShown, this, [this, key] {
        if (const Entry* entry = find(key))
            updateLabel(*entry);
    });
}

// Each group has its own form layout; equal label and spin-box widths line
// the sliders up across groups.
void ParameterInspector::alignColumns() {
    int label = 0;
    int spin = 0;
    for (const Entry& e : entries_) {
        label = std::max(label, e.label->sizeHint().width());
        if (const auto* box = qobject_cast<QAbstractSpinBox*>(e.editor->input()))
            spin = std::max(spin, box->sizeHint().width());
    }
    for (const Entry& e : entries_) {
        e.label->setMinimumWidth(label);
        if (auto* box = qobject_cast<QAbstractSpinBox*>(e.editor->input()))
            box->setMinimumWidth(spin);
    }
}

void ParameterInspector::setParameters(const scene::ParameterSet& values) {
    for (const Entry& e : entries_)
        e.editor->setValue(values.get(e.info->key));
}

void ParameterInspector::setParameter(const QString& key, const scene::ParameterValue& value) {
    if (const Entry* e = find(key))
        e->editor->setValue(value);
}

QWidget* ParameterInspector::editorFor(const QString& key) const {
    const Entry* e = find(key);
    return e ? e->editor->input() : nullptr;
}

ParameterEditor* ParameterInspector::parameterEditor(const QString& key) const {
    const Entry* e = find(key);
    return e ? e->editor : nullptr;
}

QLabel* ParameterInspector::labelFor(const QString& key) const {
    const Entry* e = find(key);
    return e ? e->label : nullptr;
}

void ParameterInspector::setFilter(const QString& text) {
    if (search_->text() != text) {
        search_->setText(text); // comes back here through textChanged
        return;
    }
    filterWords_ = text.toLower().split(' ', Qt::SkipEmptyParts);
    applyFilter();
}

bool ParameterInspector::matchesFilter(const QString& key) const {
    const Entry* e = find(key);
    return e && e->matches;
}

void ParameterInspector::applyFilter() {
    for (Section& s : sections_)
        s.matching = 0;
    int shown = 0;
    for (Entry& e : entries_) {
        e.matches = std::all_of(filterWords_.begin(), filterWords_.end(),
                                [&](const QString& w) { return e.haystack.contains(w); });
        Section& s = sections_[e.section];
        s.form->setRowVisible(e.row, e.matches);
        s.matching += e.matches ? 1 : 0;
        shown += e.matches ? 1 : 0;
    }
    for (Section& s : sections_)
        updateSection(s);
    noMatches_->setVisible(shown == 0);
}

// A section shows its rows when expanded, and always while a search is on,
// so that matches are never hidden in a collapsed group.
void ParameterInspector::updateSection(Section& s) {
    const bool filtering = !filterWords_.isEmpty();
    const bool open = s.expanded || filtering;
    s.header->setVisible(s.matching > 0 || !filtering);
    s.body->setVisible(open && (s.matching > 0 || !filtering));
    s.header->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
    s.header->setText(filtering ? tr("%1 (%2 of %3)").arg(s.name).arg(s.matching).arg(s.total)
                                : tr("%1 (%2)").arg(s.name).arg(s.total));
}

void ParameterInspector::updateLabel(const Entry& e) {
    // Bold marks a value that differs from its default, as in Qt Designer.
    QFont font = e.label->font();
    const bool modified = !e.editor->isDefault();
    if (font.bold() != modified) {
        font.setBold(modified);
        e.label->setFont(font);
    }
}

QStringList ParameterInspector::groups() const {
    QStringList out;
    for (const Section& s : sections_)
        out << s.name;
    return out;
}

QToolButton* ParameterInspector::groupHeader(const QString& group) const {
    const Section* s = findSection(group);
    return s ? s->header : nullptr;
}

void ParameterInspector::setGroupExpanded(const QString& group, bool expanded) {
    Section* s = findSection(group);
    if (!s)
        return;
    s->expanded = expanded;
    if (s->header->isChecked() != expanded) {
        const QSignalBlocker block(s->header);
        s->header->setChecked(expanded);
    }
    updateSection(*s);
}

bool ParameterInspector::isGroupExpanded(const QString& group) const {
    const Section* s = findSection(group);
    return s && s->expanded;
}

const ParameterInspector::Entry* ParameterInspector::find(const QString& key) const {
    const auto it = byKey_.constFind(key);
    return it == byKey_.constEnd() ? nullptr : &entries_[*it];
}

ParameterInspector::Section* ParameterInspector::findSection(const QString& group) {
    for (Section& s : sections_)
        if (s.name == group)
            return &s;
    return nullptr;
}

const ParameterInspector::Section* ParameterInspector::findSection(const QString& group) const {
    for (const Section& s : sections_)
        if (s.name == group)
            return &s;
    return nullptr;
}

} // namespace lpv::editor
