#include "plots/knobsview.h"

#include "plots/palette.h"

#include <QPaintEvent>
#include <QPainter>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

constexpr int kDial = 84;       //!< a knob's dial, and the horizon's circle [px]
constexpr int kGap = 16;        //!< between two drawings [px]
constexpr int kTextHeight = 36; //!< two lines under each drawing [px]
constexpr int kTiltExtra = 24;  //!< room the tilt's caption takes beyond its dial, each side [px]

} // namespace

KnobsView::KnobsView(QWidget *parent) : QWidget(parent)
{
    setObjectName(u"knobs_view"_s);
    setToolTip(tr("Each knob's angle (its pointer turns clockwise as θ grows; up is θ = 0) and "
                  "the board's tilt: the horizon turns with the roll and moves with the "
                  "pitch. docs/user-guide.md § Several knobs."));
}

void KnobsView::showSamples(const SampleBatch &batch)
{
    if (batch.isEmpty())
        return;
    const int knobsBefore = knobs();
    const bool tiltBefore = showsTilt();
    m_sample = batch.constLast();
    if (knobs() != knobsBefore || showsTilt() != tiltBefore)
        updateGeometry(); // the size hint follows the drawings, not every batch
    update();
}

void KnobsView::clear()
{
    m_sample.reset();
    updateGeometry();
    update();
}

void KnobsView::setUnits(const DisplayUnits &units)
{
    m_units = units;
    update();
}

int KnobsView::knobs() const
{
    return m_sample ? m_sample->axes() : 0;
}

bool KnobsView::showsTilt() const
{
    return m_sample && !std::isnan(m_sample->roll()) && !std::isnan(m_sample->pitch());
}

double KnobsView::knobAngle(int n) const
{
    if (!m_sample)
        return std::numeric_limits<double>::quiet_NaN();
    if (n == 1)
        return m_sample->theta;
    const AxisSample *axis = m_sample->axis(n);
    return axis ? axis->theta : std::numeric_limits<double>::quiet_NaN();
}

QString KnobsView::text() const
{
    if (!m_sample)
        return tr("No samples");
    QStringList parts;
    for (int n = 1; n <= knobs(); ++n)
        parts << tr("Knob %1: %2").arg(n).arg(m_units.format(Channel::Theta, knobAngle(n)));
    QString text = parts.join(u"; "_s);
    if (showsTilt()) {
        text += tr("; roll %1, pitch %2")
                    .arg(m_units.format(Channel::Theta, m_sample->roll()),
                         m_units.format(Channel::Theta, m_sample->pitch()));
    }
    return text;
}

QSize KnobsView::sizeHint() const
{
    const int drawings = std::max(1, knobs()) + (showsTilt() ? 1 : 0);
    return {kGap + drawings * (kDial + kGap) + kGap + (showsTilt() ? kTiltExtra : 0),
            kGap + kDial + kTextHeight};
}

QSize KnobsView::minimumSizeHint() const
{
    return sizeHint();
}

void KnobsView::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette pal = palette();
    if (!m_sample) {
        p.setPen(pal.color(QPalette::PlaceholderText));
        p.drawText(rect(), Qt::AlignCenter, tr("No samples"));
        return;
    }
    const QColor line = pal.color(QPalette::WindowText);
    const QColor pointer = palette::channel(Channel::Theta);
    auto caption = [&](const QRect &dial, const QString &title, const QString &value, int wider) {
        const QRect below(dial.left() - kGap / 2 - wider / 2, dial.bottom() + 4,
                          dial.width() + kGap + wider, kTextHeight - 4);
        p.setPen(line);
        p.drawText(below, Qt::AlignHCenter | Qt::AlignTop, title + u'\n' + value);
    };

    int x = kGap;
    for (int n = 1; n <= knobs(); ++n, x += kDial + kGap) {
        const QRect dial(x, kGap, kDial, kDial);
        p.setPen(QPen(line, 1.5));
        p.setBrush(pal.color(QPalette::Base));
        p.drawEllipse(dial);
        const double theta = knobAngle(n);
        if (std::isfinite(theta)) {
            // Up is θ = 0; the pointer turns clockwise as θ grows.
            const QPointF c = QRectF(dial).center();
            const double r = 0.42 * kDial;
            p.setPen(QPen(pointer, 3, Qt::SolidLine, Qt::RoundCap));
            p.drawLine(c, c + QPointF(r * std::sin(theta), -r * std::cos(theta)));
        }
        caption(dial, tr("Knob %1").arg(n), m_units.format(Channel::Theta, theta), 0);
    }
    if (showsTilt()) {
        const QRect dial(x, kGap, kDial, kDial);
        p.setPen(QPen(line, 1.5));
        p.setBrush(pal.color(QPalette::Base));
        p.drawEllipse(dial);
        // The horizon: turned by the roll, moved down as the board pitches up (±π/2 is the rim).
        p.save();
        p.setClipRegion(QRegion(dial, QRegion::Ellipse));
        p.translate(QRectF(dial).center());
        p.rotate(-m_sample->roll() * 180 / std::numbers::pi);
        const double shift = std::clamp(m_sample->pitch() / (std::numbers::pi / 2), -1.0, 1.0);
        p.translate(0, shift * kDial / 2);
        p.setPen(QPen(pointer, 3));
        p.drawLine(QPointF(-kDial, 0), QPointF(kDial, 0));
        p.restore();
        // Roll and pitch on a line each, wider than the dial: the last drawing has the room.
        caption(dial, tr("roll %1").arg(m_units.format(Channel::Theta, m_sample->roll())),
                tr("pitch %1").arg(m_units.format(Channel::Theta, m_sample->pitch())),
                2 * kTiltExtra);
    }
}

} // namespace hatpic
