#include "plots/axistitle.h"

#include "plots/qcp.h"

namespace hatpic {

QCPItemText *cornerTitle(const QCPAxisRect *rect)
{
    QCustomPlot *plot = rect->parentPlot();
    for (int i = 0; i < plot->itemCount(); ++i) {
        auto *text = qobject_cast<QCPItemText *>(plot->item(i));
        if (text && text->objectName() == QLatin1String(kCornerTitleName) &&
            text->clipAxisRect() == rect)
            return text;
    }
    return nullptr;
}

QCPItemText *setCornerTitle(QCPAxisRect *rect, const QString &text, Qt::Alignment corner)
{
    QCPItemText *title = cornerTitle(rect);
    if (!title) {
        QCustomPlot *plot = rect->parentPlot();
        title = new QCPItemText(plot);
        title->setObjectName(QLatin1String(kCornerTitleName));
        title->setClipAxisRect(rect);
        title->setClipToAxisRect(true);
        title->setLayer(QStringLiteral("legend")); // over the curves
        title->position->setAxisRect(rect);
        title->position->setType(QCPItemPosition::ptAxisRectRatio);
        title->position->setCoords(corner & Qt::AlignRight ? 1 : 0,
                                   corner & Qt::AlignBottom ? 1 : 0);
        title->setPositionAlignment(corner);
        title->setPadding(QMargins(4, 1, 4, 2));
        title->setColor(plot->palette().color(QPalette::Text));
        QColor fill = plot->palette().color(QPalette::Base);
        fill.setAlpha(200);
        title->setBrush(fill);
    }
    title->setText(text);
    return title;
}

} // namespace hatpic
