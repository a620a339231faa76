// The plots' own actions for the View and File menus and the toolbar: window length,
// autoscale, series and bands on/off, and the image and CSV exports (with their dialogs).
// Each action follows the PlotPanel both ways, so a legend click checks its menu entry.
#pragma once

#include <QObject>

#include <array>
#include <functional>

class QAction;
class QActionGroup;
class QMenu;
class QWidget;

namespace hatpic {

class PlotPanel;

class PlotActions : public QObject
{
    Q_OBJECT
public:
    static constexpr std::array<double, 4> kWindowChoices{5, 10, 30, 60}; //!< [s]

    PlotActions(PlotPanel *plots, QWidget *dialogParent);

    QList<QAction *> windowActions() const; //!< "5 s" … "60 s", exclusive
    //! Checks the entry of `seconds` (if it is one of the choices).
    void checkWindow(double seconds);
    QAction *autoscaleAction() const { return m_autoscale; }
    QAction *exportImageAction() const { return m_exportImage; } //!< Ctrl+E
    QAction *exportCsvAction() const { return m_exportCsv; }     //!< Ctrl+Shift+E
    QAction *measureAction() const { return m_measure; }         //!< Ctrl+M, the two cursors
    //! What an exported picture is noted with (profile, parameters), asked at each export.
    void setCaptionSource(std::function<QString()> caption) { m_caption = std::move(caption); }
    //! One checkable entry per series, then the bands.
    void addSeriesActions(QMenu *menu) const;

Q_SIGNALS:
    void windowChosen(double seconds);
    void statusMessage(const QString &message);

private:
    void exportImage();
    void exportCsv();

    PlotPanel *m_plots;
    QWidget *m_dialogParent;
    QActionGroup *m_window = nullptr;
    QAction *m_autoscale = nullptr;
    QAction *m_exportImage = nullptr;
    QAction *m_exportCsv = nullptr;
    QAction *m_measure = nullptr;
    std::function<QString()> m_caption;
    QList<QAction *> m_series;
    QAction *m_bands = nullptr;
};

} // namespace hatpic
