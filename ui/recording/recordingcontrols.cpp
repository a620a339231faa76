#include "recording/recordingcontrols.h"

#include "plots/palette.h"
#include "recording/recordingplandialog.h"

#include <QAction>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QStandardPaths>
#include <QToolButton>

namespace hatpic {

namespace {

QIcon recordIcon()
{
    QPixmap pixmap(32, 32);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(120, 0, 0), 1.5));
    painter.setBrush(QColor(211, 47, 47));
    painter.drawEllipse(QRectF(6, 6, 20, 20));
    return QIcon(pixmap);
}

} // namespace

RecordingControls::RecordingControls(QWidget *parent) : QWidget(parent)
{
    m_action = new QAction(recordIcon(), tr("&Record…"), this);
    m_action->setObjectName(QStringLiteral("recordAction"));
    m_action->setCheckable(true);
    m_action->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_action->setToolTip(tr("Record the live data to a CSV file (Ctrl+R); again to stop"));
    connect(m_action, &QAction::triggered, this, &RecordingControls::onTriggered);

    m_planAction = new QAction(tr("Recording &Options…"), this);
    m_planAction->setObjectName(QStringLiteral("recordingPlanAction"));
    m_planAction->setToolTip(
        tr("Start now, on the next push or at a threshold; time before the trigger; length"));
    // The toolbar button shows the icon text, which stays "⚙" whenever the action changes (a
    // recording disables it): once its full text widened the toolbar past 1280 px.
    m_planAction->setIconText(QStringLiteral("⚙"));
    connect(m_planAction, &QAction::triggered, this, &RecordingControls::onPlanTriggered);
    m_planChooser = [this](const RecordingPlan &plan) -> std::optional<RecordingPlan> {
        RecordingPlanDialog dialog(this);
        dialog.setPlan(plan);
        if (dialog.exec() != QDialog::Accepted)
            return std::nullopt;
        return dialog.plan();
    };

    m_button = new QToolButton(this);
    m_button->setDefaultAction(m_action);
    m_button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    auto *planButton = new QToolButton(this);
    planButton->setObjectName(QStringLiteral("recordingPlanButton"));
    planButton->setDefaultAction(m_planAction);
    m_label = new QLabel(this);
    m_label->setObjectName(QStringLiteral("recordingStatus"));
    m_label->setMinimumWidth(m_label->fontMetrics().horizontalAdvance(
        QStringLiteral("● 00:00 · 999.9 MB · 999999 samples")));
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 0, 4, 0);
    layout->addWidget(m_button);
    layout->addWidget(planButton);
    layout->addWidget(m_label, 1);

    m_chooser = [this](const QString &suggested) {
        return QFileDialog::getSaveFileName(this, tr("Record to"), inExistingFolder(suggested),
                                            tr("CSV recordings (*.csv)"));
    };
    refresh();
}

QString RecordingControls::suggestedPath(const QString &directory)
{
    QString dir = directory;
    if (dir.isEmpty())
        dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (dir.isEmpty())
        dir = QDir::homePath();
    const QString name =
        QDateTime::currentDateTime().toString(QStringLiteral("'hatpic-'yyyyMMdd-HHmmss'.csv'"));
    return QDir(dir).filePath(name);
}

QString RecordingControls::inExistingFolder(const QString &path)
{
    const QFileInfo info(path);
    if (info.absoluteDir().exists())
        return path;
    return QDir::home().filePath(info.fileName());
}

QString RecordingControls::chooseRecordingToOpen()
{
    QString dir = m_directory;
    if (dir.isEmpty() || !QDir(dir).exists())
        dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (dir.isEmpty() || !QDir(dir).exists())
        dir = QDir::homePath();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open recording"), dir, tr("CSV recordings (*.csv)"));
    if (!path.isEmpty())
        m_directory = QFileInfo(path).absolutePath();
    return path;
}

void RecordingControls::setPlan(const RecordingPlan &plan)
{
    m_plan = plan.sanitized();
    refresh();
}

void RecordingControls::onPlanTriggered()
{
    if (!m_planChooser)
        return;
    if (const std::optional<RecordingPlan> plan = m_planChooser(m_plan))
        setPlan(*plan);
}

void RecordingControls::onTriggered()
{
    if (m_status.active || m_status.armed) {
        Q_EMIT stopRequested();
    } else {
        QString path = m_chooser ? m_chooser(suggestedPath(m_directory)) : QString();
        if (!path.isEmpty()) {
            if (QFileInfo(path).suffix().isEmpty())
                path += QStringLiteral(".csv");
            m_directory = QFileInfo(path).absolutePath();
            Q_EMIT startRequested(path);
        }
    }
    refresh(); // the check state follows the session, not the click
}

void RecordingControls::setStatus(const RecordingStatus &status)
{
    m_status = status;
    if (status.active || status.armed)
        m_note.clear(); // a new recording: the last one's note is history
    refresh();
}

void RecordingControls::setNote(const QString &note)
{
    m_note = note;
    refresh();
}

void RecordingControls::setCanRecord(bool connected)
{
    m_canRecord = connected;
    refresh();
}

void RecordingControls::refresh()
{
    const bool busy = m_status.active || m_status.armed;
    m_action->setChecked(busy);
    m_action->setEnabled(m_canRecord || busy);
    m_action->setText(m_status.active  ? tr("Stop &recording")
                      : m_status.armed ? tr("Cancel &recording")
                                       : tr("&Record…"));
    m_planAction->setEnabled(!busy);
    m_label->setText(statusText());
    QStringList tip{m_status.path};
    if (m_status.waiting) {
        tip << tr("The link to the device is lost: the recording stays open and goes on in the "
                  "same file when the device is back.");
    }
    if (m_status.gaps > 0) {
        tip << tr("Link losses during this recording: %1. Each gap is an event in the file "
                  "(\"gap: …\"), on the first row after it.")
                   .arg(m_status.gaps);
    }
    if (!m_note.isEmpty())
        tip << m_note;
    m_label->setToolTip(tip.join(u'\n'));
    // A red that reads at 3:1 on the light and on the dark theme's window; waiting for the
    // device, and a note on how the last recording ended, in the caution colour.
    const bool caution = m_status.waiting || (!busy && !m_note.isEmpty());
    m_label->setStyleSheet(
        caution ? QStringLiteral("color: %1; font-weight: bold;").arg(palette::kCautionText.name())
        : busy  ? QStringLiteral("color: #e53935; font-weight: bold;")
                : QString());
}

QString RecordingControls::gapsText() const
{
    if (m_status.gaps == 0)
        return {};
    return m_status.gaps == 1 ? tr(" · 1 gap") : tr(" · %1 gaps").arg(m_status.gaps);
}

QString RecordingControls::statusText() const
{
    if (m_status.armed)
        return tr("◌ Armed: waiting for %1").arg(RecordingPlanDialog::describeTrigger(m_plan));
    QString text;
    if (m_status.active && m_plan.duration_s > 0) {
        text = tr("● %1 of %2 · %3 · %4 samples")
                   .arg(formatDuration(m_status.seconds), formatDuration(m_plan.duration_s),
                        formatBytes(m_status.bytes))
                   .arg(m_status.samples);
    } else if (m_status.active) {
        text = tr("● %1 · %2 · %3 samples")
                   .arg(formatDuration(m_status.seconds), formatBytes(m_status.bytes))
                   .arg(m_status.samples);
    } else if (!m_status.error.isEmpty()) {
        return tr("Recording stopped: %1").arg(m_status.error);
    } else if (!m_status.path.isEmpty()) {
        text = tr("Saved %1 (%2)")
                   .arg(QFileInfo(m_status.path).fileName(), formatBytes(m_status.bytes));
    } else {
        return {};
    }
    if (m_status.waiting) // short: the banner says the link is lost, the tooltip the rest
        return text + tr(" · waiting for the device");
    text += gapsText();
    if (!m_status.active && !m_note.isEmpty())
        text += u" — " + m_note;
    return text;
}

QString RecordingControls::formatBytes(qint64 bytes)
{
    if (bytes < 1000)
        return tr("%1 B").arg(bytes);
    if (bytes < 1000 * 1000)
        return tr("%1 kB").arg(bytes / 1e3, 0, 'f', 1);
    if (bytes < 1000LL * 1000 * 1000)
        return tr("%1 MB").arg(bytes / 1e6, 0, 'f', 1);
    return tr("%1 GB").arg(bytes / 1e9, 0, 'f', 2);
}

QString RecordingControls::formatDuration(double seconds)
{
    const qint64 total = static_cast<qint64>(std::max(seconds, 0.0));
    const qint64 h = total / 3600;
    const qint64 m = (total / 60) % 60;
    const qint64 s = total % 60;
    auto two = [](qint64 v) { return QString::number(v).rightJustified(2, u'0'); };
    if (h > 0)
        return QString::number(h) % u':' % two(m) % u':' % two(s);
    return two(m) % u':' % two(s);
}

} // namespace hatpic
