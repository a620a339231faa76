#include "plots/plottheme.h"

#include "plots/axistitle.h"
#include "plots/palette.h"
#include "plots/qcp.h"

#include <QEvent>
#include <QPalette>

namespace hatpic::plottheme {

QColor mix(const QColor &a, const QColor &b, double fa)
{
    return QColor::fromRgbF(float(a.redF() * fa + b.redF() * (1 - fa)),
                            float(a.greenF() * fa + b.greenF() * (1 - fa)),
                            float(a.blueF() * fa + b.blueF() * (1 - fa)));
}

namespace {

class Follower : public QObject
{
public:
    explicit Follower(QCustomPlot *plot) : QObject(plot), m_plot(plot)
    {
        plot->installEventFilter(this);
    }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (watched == m_plot && event->type() == QEvent::PaletteChange)
            apply(m_plot, m_plot->palette());
        return false;
    }

private:
    QCustomPlot *m_plot;
};

} // namespace

bool isDark(const QPalette &palette)
{
    return palette.color(QPalette::Window).lightness() < 128;
}

QCPScatterStyle livePointStyle(const QPalette &palette)
{
    return QCPScatterStyle(QCPScatterStyle::ssDisc, QPen(palette.color(QPalette::Text), 2),
                           QBrush(palette::kLivePoint), 11);
}

void apply(QCustomPlot *plot, const QPalette &palette)
{
    const QColor base = palette.color(QPalette::Base);
    const QColor text = palette.color(QPalette::Text);
    const QColor grid = mix(text, base, 0.22);
    const QColor subGrid = mix(text, base, 0.1);
    plot->setBackground(base);
    for (QCPAxisRect *rect : plot->axisRects()) {
        for (QCPAxis *axis : rect->axes()) {
            axis->setBasePen(QPen(text, 0));
            axis->setTickPen(QPen(text, 0));
            axis->setSubTickPen(QPen(text, 0));
            axis->setTickLabelColor(text);
            axis->setLabelColor(text);
            axis->grid()->setPen(QPen(grid, 0, Qt::DotLine));
            axis->grid()->setSubGridPen(QPen(subGrid, 0, Qt::DotLine));
            axis->grid()->setZeroLinePen(QPen(grid, 0));
        }
    }
    for (QCPLayoutElement *element : plot->plotLayout()->elements(true)) {
        auto *legend = qobject_cast<QCPLegend *>(element);
        if (!legend)
            continue;
        QColor fill = base;
        fill.setAlpha(220);
        legend->setBrush(fill);
        legend->setBorderPen(QPen(grid, 0));
        legend->setTextColor(text);
        for (int i = 0; i < legend->itemCount(); ++i) {
            QCPAbstractLegendItem *item = legend->item(i); // null: a gap in a wrapped grid
            if (item && item->textColor() != kHiddenLegendText)
                item->setTextColor(text);
        }
    }
    for (int i = 0; i < plot->itemCount(); ++i) {
        auto *title = qobject_cast<QCPItemText *>(plot->item(i));
        if (!title || title->objectName() != QLatin1String(kCornerTitleName))
            continue;
        QColor fill = base;
        fill.setAlpha(200);
        title->setBrush(fill);
        title->setColor(text);
    }
    plot->replot();
}

void follow(QCustomPlot *plot)
{
    new Follower(plot);
    apply(plot, plot->palette());
}

} // namespace hatpic::plottheme
