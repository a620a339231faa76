// The two measuring cursors of the time plots, A and B: a line through every plot each, their
// times, Δt = t_B − t_A (and 1/Δt, the frequency of one period between them) and, in the
// legends, Δvalue = value(B) − value(A) of every visible series in display units.
//
// The cursors sit on samples: a cursor placed at a time moves to the nearest sample of what the
// plots show. Mouse: a click in a plot places A, Shift+click places B, a cursor's line can be
// dragged. Keyboard (the plots focused): A or B picks the cursor, Left and Right move it by a
// pixel's worth of time (at least one sample), with Shift by ten.
#pragma once

#include "plots/channel.h"

#include <QList>
#include <QObject>

#include <array>
#include <optional>

class QCPItemStraightLine;
class QCPItemText;
class QEvent;
class QMouseEvent;

namespace hatpic {

class PlotPanel;

class MeasureCursors : public QObject
{
    Q_OBJECT
public:
    static constexpr int kCount = 2;      //!< A and B
    static constexpr int kGrabPixels = 6; //!< a press this close to a line drags it [px]

    //! The difference of one series between the cursors, in display units.
    struct Delta
    {
        Channel channel = Channel::Theta;
        double a = 0;     //!< value at A
        double b = 0;     //!< value at B
        double delta = 0; //!< b − a
    };
    struct Readout
    {
        double tA = 0;       //!< [s]
        double tB = 0;       //!< [s]
        double dt = 0;       //!< tB − tA [s]
        QList<Delta> deltas; //!< every visible series, in channel order
    };

    //! Draws into `panel`'s plots; off until setEnabled(true).
    explicit MeasureCursors(PlotPanel *panel);

    //! On: the cursors show (placed at a third and two thirds of the view if never placed).
    void setEnabled(bool on);
    bool isEnabled() const { return m_enabled; }

    //! Places cursor `which` (0 = A, 1 = B) at the sample nearest `t` [s].
    void setTime(int which, double t);
    std::optional<double> time(int which) const { return m_times[which]; }
    //! The cursor the keys move.
    void setActive(int which);
    int active() const { return m_active; }

    //! Δt and the Δ of every visible series; nullopt while off or with no data.
    std::optional<Readout> readout() const;
    //! "Δt = 0.500 s (2.00 Hz)"; empty when there is no readout.
    QString dtText() const;
    //! Names the visible graphs "θ Δ +3.21 °" (call after the panel named them).
    void nameGraphs() const;

    //! The panel's event filter passes the plot's events here; true when used up.
    bool handleEvent(QEvent *event);

Q_SIGNALS:
    void changed();

private:
    bool onPress(QMouseEvent *event);
    bool onKey(int key, bool shift);
    std::optional<double> snap(double t) const;
    void step(int direction, int pixels);
    void updateItems();
    std::optional<double> timeAtPixel(double x) const;

    PlotPanel *m_panel;
    bool m_enabled = false;
    std::array<std::optional<double>, kCount> m_times{};
    int m_active = 0;
    int m_dragging = -1; //!< the cursor being dragged, −1: none
    std::array<QList<QCPItemStraightLine *>, kCount> m_lines;
    std::array<QCPItemText *, kCount> m_names{};
    QCPItemText *m_dt = nullptr;
};

} // namespace hatpic
