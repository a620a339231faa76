// A path through the recent (x, y) states of two quantities, drawn in pieces that fade with
// age: the newest piece opaque, the oldest faint. Loops (hysteresis) and back-and-forth jumps
// (chatter) stand out, and the direction of travel reads from the fading.
//
// Not a widget: it owns QCustomPlot curves, which the plot deletes with itself.
#pragma once

#include "plots/channel.h"

#include <QColor>
#include <QVector>

#include <array>

class QCPAxis;
class QCPCurve;

namespace hatpic {

class SampleBuffer;

class FadingTrail
{
public:
    static constexpr int kPieces = 8;       //!< age steps, each its own opacity
    static constexpr int kMaxPoints = 4000; //!< more samples are thinned evenly
    static constexpr int kOldestAlpha = 30; //!< opacity of the oldest piece (of 255)

    //! Curves on the axes `x`, `y`, the newest one named `name` in the plot's legend.
    FadingTrail(QCPAxis *x, QCPAxis *y, const QColor &colour, const QString &name);

    //! The samples of `source` with times in [t0, t1], oldest first, as (x, y) = (value of
    //! `xChannel` × `xScale`, value of `yChannel` × `yScale`); samples where either is NaN
    //! break the path.
    void setFromBuffer(const SampleBuffer &source, double t0, double t1, Channel xChannel,
                       double xScale, Channel yChannel, double yScale);
    void clear();
    void setLayer(const QString &layer);

    //! The points drawn, after thinning.
    qsizetype pointCount() const { return m_points; }
    //! The piece of age `piece` (0 = oldest … kPieces − 1 = newest).
    QCPCurve *piece(int piece) const { return m_pieces[piece]; }

private:
    std::array<QCPCurve *, kPieces> m_pieces{};
    qsizetype m_points = 0;
};

} // namespace hatpic
