#include "plots/xyview.h"

#include "plots/fadingtrail.h"
#include "plots/palette.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace hatpic {

namespace {

//! `axis` fitted to the values of `curves`' keys or values, with a margin.
void fitAxis(QCPAxis *axis, double lo, double hi)
{
    if (!(lo <= hi))
        return;
    const double margin = std::max(0.08 * (hi - lo), 1e-6 + 1e-3 * std::abs(hi));
    axis->setRange(lo - margin, hi + margin);
}

} // namespace

XyView::XyView(PlotPanel *panel, QWidget *parent) : QWidget(parent), m_panel(panel)
{
    m_x = new QComboBox(this);
    m_y = new QComboBox(this);
    m_x->setObjectName(QStringLiteral("xyXChannel"));
    m_y->setObjectName(QStringLiteral("xyYChannel"));
    for (Channel channel : kAllChannels) {
        m_x->addItem(channelLabel(channel), channelIndex(channel));
        m_y->addItem(channelLabel(channel), channelIndex(channel));
    }
    auto *choice = new QHBoxLayout;
    choice->addWidget(new QLabel(tr("Horizontal:"), this));
    choice->addWidget(m_x);
    choice->addSpacing(12);
    choice->addWidget(new QLabel(tr("Vertical:"), this));
    choice->addWidget(m_y);
    choice->addStretch(1);

    m_plot = new QCustomPlot(this);
    m_plot->setObjectName(QStringLiteral("xyPlot"));
    m_plot->setMinimumSize(240, 180);
    QCPAxisRect *rect = m_plot->axisRect();
    m_trail =
        std::make_unique<FadingTrail>(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft),
                                      palette::channel(Channel::Theta), tr("path"));
    m_point = m_plot->addGraph();
    m_point->setName(tr("newest"));
    m_point->setLineStyle(QCPGraph::lsNone);
    m_point->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssDisc, palette::kLivePoint, palette::kLivePoint, 8));
    m_plot->setToolTip(tr("One channel against another over the time plots' range; older "
                          "samples fainter, the dot is the newest."));

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 0);
    layout->addLayout(choice);
    layout->addWidget(m_plot, 1);

    setChannels(Channel::Theta, Channel::Omega);
    auto chosen = [this] { refresh(); };
    connect(m_x, &QComboBox::currentIndexChanged, this, chosen);
    connect(m_y, &QComboBox::currentIndexChanged, this, chosen);
    connect(panel, &PlotPanel::repainted, this, [this] {
        if (isVisible())
            refresh();
    });
}

XyView::~XyView() = default;

void XyView::setChannels(Channel x, Channel y)
{
    m_x->setCurrentIndex(channelIndex(x));
    m_y->setCurrentIndex(channelIndex(y));
    refresh();
}

Channel XyView::xChannel() const
{
    return kAllChannels[std::clamp(m_x->currentIndex(), 0, kChannelCount - 1)];
}

Channel XyView::yChannel() const
{
    return kAllChannels[std::clamp(m_y->currentIndex(), 0, kChannelCount - 1)];
}

void XyView::refresh()
{
    const Channel x = xChannel();
    const Channel y = yChannel();
    const DisplayUnits &units = m_panel->units();
    QCPAxisRect *rect = m_plot->axisRect();
    rect->axis(QCPAxis::atBottom)->setLabel(channelLabel(x) % u" [" % units.unit(x) % u']');
    rect->axis(QCPAxis::atLeft)->setLabel(channelLabel(y) % u" [" % units.unit(y) % u']');
    // The y quantity's colour: the path is how y moves as x does.
    for (int i = 0; i < FadingTrail::kPieces; ++i) {
        QPen pen = m_trail->piece(i)->pen();
        QColor c = palette::channel(y);
        c.setAlpha(pen.color().alpha());
        pen.setColor(c);
        m_trail->piece(i)->setPen(pen);
    }

    const SampleBuffer *src = m_panel->shownSource();
    const double t0 = m_panel->viewStart();
    const double t1 = std::min(m_panel->viewEnd(), m_panel->dataEnd().value_or(INFINITY));
    m_point->data()->clear();
    if (!src || src->isEmpty()) {
        m_trail->clear();
        m_plot->replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    m_trail->setFromBuffer(*src, t0, t1, x, units.scale(x), y, units.scale(y));
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    for (int i = 0; i < FadingTrail::kPieces; ++i) {
        const auto data = m_trail->piece(i)->data();
        for (auto it = data->constBegin(); it != data->constEnd(); ++it) {
            if (std::isfinite(it->key) && std::isfinite(it->value)) {
                xlo = std::min(xlo, it->key);
                xhi = std::max(xhi, it->key);
                ylo = std::min(ylo, it->value);
                yhi = std::max(yhi, it->value);
            }
        }
    }
    const qsizetype newest = src->upperBound(t1) - 1;
    if (newest >= 0 && src->time(newest) >= t0)
        m_point->setData(QVector<double>{src->value(x, newest) * units.scale(x)},
                         QVector<double>{src->value(y, newest) * units.scale(y)}, true);
    fitAxis(rect->axis(QCPAxis::atBottom), xlo, xhi);
    fitAxis(rect->axis(QCPAxis::atLeft), ylo, yhi);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace hatpic
