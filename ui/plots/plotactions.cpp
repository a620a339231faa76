#include "plots/plotactions.h"

#include "plots/imagesizedialog.h"
#include "plots/measurecursors.h"
#include "plots/plotpanel.h"

#include <QAction>
#include <QActionGroup>
#include <QDir>
#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>
#include <QStandardPaths>

namespace hatpic {

namespace {

QString suggestedExport(const QString &name)
{
    QString dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (dir.isEmpty())
        dir = QDir::homePath();
    return QDir(dir).filePath(name);
}

} // namespace

PlotActions::PlotActions(PlotPanel *plots, QWidget *dialogParent)
    : QObject(plots), m_plots(plots), m_dialogParent(dialogParent)
{
    m_window = new QActionGroup(this);
    int key = Qt::Key_1; // Ctrl+1 … Ctrl+4: the window lengths, shortest first
    for (double seconds : kWindowChoices) {
        // "5 s" on the toolbar, the whole name in the menu and the shortcut table.
        auto *action = new QAction(tr("Window length %1 s").arg(seconds), m_window);
        action->setIconText(tr("%1 s").arg(seconds));
        action->setShortcut(QKeySequence(Qt::CTRL | Qt::Key(key++)));
        action->setCheckable(true);
        action->setData(seconds);
        action->setToolTip(tr("Show the last %1 seconds").arg(seconds));
        action->setChecked(seconds == plots->windowLength());
        connect(action, &QAction::triggered, this,
                [this, seconds] { Q_EMIT windowChosen(seconds); });
    }

    m_autoscale = new QAction(tr("&Autoscale"), this);
    m_autoscale->setCheckable(true);
    m_autoscale->setChecked(plots->autoscale());
    m_autoscale->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A));
    m_autoscale->setToolTip(tr("Fit the vertical axes to the data; off keeps them fixed and the "
                               "mouse drags and zooms them"));
    connect(m_autoscale, &QAction::toggled, plots, &PlotPanel::setAutoscale);
    connect(plots, &PlotPanel::autoscaleChanged, m_autoscale, &QAction::setChecked);

    for (Channel channel : kAllChannels) {
        auto *action = new QAction(channelLabel(channel), this);
        action->setCheckable(true);
        action->setChecked(plots->isChannelVisible(channel));
        connect(action, &QAction::toggled, this,
                [this, channel](bool on) { m_plots->setChannelVisible(channel, on); });
        m_series << action;
    }
    connect(plots, &PlotPanel::channelVisibilityChanged, this,
            [this](Channel c, bool on) { m_series.at(channelIndex(c))->setChecked(on); });
    m_bands = new QAction(tr("Dead-zone and notch bands"), this);
    m_bands->setCheckable(true);
    m_bands->setChecked(plots->bandsVisible());
    connect(m_bands, &QAction::toggled, plots, &PlotPanel::setBandsVisible);
    connect(plots, &PlotPanel::bandsVisibilityChanged, m_bands, &QAction::setChecked);

    m_measure = new QAction(tr("&Measure (Cursors A and B)"), this);
    m_measure->setIconText(tr("Measure"));
    m_measure->setObjectName(QStringLiteral("measureAction"));
    m_measure->setCheckable(true);
    m_measure->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_M));
    m_measure->setToolTip(tr("Two cursors A and B with Δt and the Δ of every series (Ctrl+M). "
                             "Click: A, Shift+click: B, drag a line to move it; on the plots, "
                             "A or B picks one, ← → move it (Shift: by ten)"));
    connect(m_measure, &QAction::toggled, plots->measure(), &MeasureCursors::setEnabled);

    m_exportImage = new QAction(tr("Export View as &Image…"), this);
    m_exportImage->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    m_exportImage->setToolTip(tr("Save the three plots as PNG (at a chosen size), SVG or PDF, "
                                 "noted with the profile and parameters (Ctrl+E)"));
    connect(m_exportImage, &QAction::triggered, this, &PlotActions::exportImage);
    m_exportCsv = new QAction(tr("Export Visible &Data as CSV…"), this);
    m_exportCsv->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    m_exportCsv->setToolTip(tr("Save the samples of the visible time range (Ctrl+Shift+E)"));
    connect(m_exportCsv, &QAction::triggered, this, &PlotActions::exportCsv);
}

QList<QAction *> PlotActions::windowActions() const
{
    return m_window->actions();
}

void PlotActions::checkWindow(double seconds)
{
    for (QAction *action : m_window->actions())
        action->setChecked(action->data().toDouble() == seconds);
}

void PlotActions::addSeriesActions(QMenu *menu) const
{
    menu->addActions(m_series);
    menu->addSeparator();
    menu->addAction(m_bands);
}

void PlotActions::exportImage()
{
    const QString path = QFileDialog::getSaveFileName(
        m_dialogParent, tr("Export view"), suggestedExport(QStringLiteral("hatpic-view.png")),
        tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"));
    if (path.isEmpty())
        return;
    PlotImageOptions options{m_plots->customPlot()->size(), 1.0, {}};
    if (plotImageFormat(path) != PlotImageFormat::Pdf) {
        ImageSizeDialog size(m_plots->customPlot()->size(), plotImageFormat(path), m_dialogParent);
        if (size.exec() != QDialog::Accepted)
            return;
        options = size.options();
    }
    if (m_caption)
        options.caption = m_caption();
    QString error;
    if (!m_plots->exportImage(path, options, &error))
        QMessageBox::warning(m_dialogParent, tr("Export view"), error);
    else
        Q_EMIT statusMessage(tr("Saved %1").arg(path));
}

void PlotActions::exportCsv()
{
    const QString path = QFileDialog::getSaveFileName(
        m_dialogParent, tr("Export visible data"),
        suggestedExport(QStringLiteral("hatpic-view.csv")), tr("CSV (*.csv)"));
    if (path.isEmpty())
        return;
    QString error;
    const qsizetype rows = m_plots->exportCsv(path, &error);
    if (rows < 0)
        QMessageBox::warning(m_dialogParent, tr("Export visible data"), error);
    else
        Q_EMIT statusMessage(tr("Saved %1 samples to %2").arg(rows).arg(path));
}

} // namespace hatpic
