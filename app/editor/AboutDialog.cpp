#include "AboutDialog.h"

#include "lpv/app/VersionInfo.h"
#include "lpv/renderer/GlContext.h"

#include <QApplication>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QLabel>
#include <QGuiApplication>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace lpv::editor {

namespace {

// The viewport's render context: the driver the editor really renders with,
// which can differ from the headless one `lpv --version` reports.
std::string viewportOpenGl(const std::optional<renderer::GlInfo>& info) {
    if (!info)
        return "unavailable: the viewport has not rendered yet";
    return app::describeOpenGl(*info) + ", Qt platform " + QGuiApplication::platformName().toStdString();
}

} // namespace

QString aboutReport(const std::optional<renderer::GlInfo>& renderer) {
    app::VersionReport report = app::collectVersionReport("LPV Studio");
    report.openGl = viewportOpenGl(renderer);
    report.gl = renderer; // GPU, driver and EGL platform on lines of their own
    // Qt first: the editor's own toolkit. The loaded library can be newer than the headers.
    const std::string qtNote = std::string(qVersion()) == QT_VERSION_STR
                                   ? "loaded"
                                   : std::string("loaded; built against ") + QT_VERSION_STR;
    report.libraries.insert(report.libraries.begin(), {"Qt", qVersion(), qtNote});
    return QString::fromStdString(app::formatVersionReport(report));
}

AboutDialog::AboutDialog(const std::optional<renderer::GlInfo>& renderer, QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("About LPV Studio"));
    auto* layout = new QVBoxLayout(this);

    auto* header = new QLabel(this);
    header->setTextFormat(Qt::RichText);
    header->setText(tr("<h2>LPV Studio %1</h2>"
                       "<p>Real-time global illumination with Cascaded Light Propagation Volumes:<br>"
                       "an editor (lpvstudio) and a command-line tool (lpv).</p>")
                        .arg(QString::fromStdString(app::buildInfo().version)));
    layout->addWidget(header);

    text_ = new QPlainTextEdit(aboutReport(renderer), this);
    text_->setReadOnly(true);
    text_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    text_->setLineWrapMode(QPlainTextEdit::NoWrap);
    text_->setMinimumSize(760, 300);
    layout->addWidget(text_);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton* copy = buttons->addButton(tr("&Copy"), QDialogButtonBox::ActionRole);
    connect(copy, &QPushButton::clicked, this, [this] { QApplication::clipboard()->setText(reportText()); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

QString AboutDialog::reportText() const {
    return text_->toPlainText();
}

} // namespace lpv::editor
