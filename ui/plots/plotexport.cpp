#include "plots/plotexport.h"

#include "model/paramtable.h"
#include "plots/qcp.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QPainter>
#include <QStringList>
#include <QSvgGenerator>

#include <algorithm>

namespace hatpic {

namespace {

constexpr int kMargin = 8;         //!< around the caption [layout px]
constexpr int kMinPlotHeight = 80; //!< the plot keeps at least this much [layout px]

QString tr(const char *text)
{
    return QCoreApplication::translate("hatpic::PlotExport", text);
}

//! Draws the caption across `width` at the top; returns the height it took.
int drawCaption(QPainter &painter, const QFont &font, int width, const QString &caption)
{
    if (caption.isEmpty())
        return 0;
    painter.setFont(font);
    const QRect box(kMargin, kMargin, std::max(width - 2 * kMargin, 1), 10'000);
    const QRect used = painter.fontMetrics().boundingRect(
        box, Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, caption);
    painter.setPen(Qt::black);
    painter.drawText(box, Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, caption);
    return used.height() + 2 * kMargin;
}

//! The caption, then the plot under it, on `painter` over `size` layout pixels.
void paint(QCustomPlot *plot, QCPPainter &painter, const QSize &size, const QString &caption)
{
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    painter.fillRect(QRect(QPoint(0, 0), size), Qt::white);
    const int header = drawCaption(painter, plot->font(), size.width(), caption);
    painter.translate(0, header);
    plot->toPainter(&painter, size.width(), std::max(size.height() - header, kMinPlotHeight));
}

} // namespace

QString plotCaption(const QString &profileName, const std::optional<DeviceParams> &params,
                    const HostParams &host)
{
    QStringList parts;
    if (params) {
        for (const DeviceFieldSpec &field : kDeviceFields) {
            parts << QString::fromUtf8(field.symbol.data(), qsizetype(field.symbol.size())) %
                         u" = " % QString::number((*params).*field.member, 'g', 6) % u' ' %
                         QString::fromUtf8(field.unit.data(), qsizetype(field.unit.size()));
        }
    } else {
        parts << tr("parameters unknown");
    }
    parts << tr("tau_limit = %1 N·m").arg(host.tau_limit, 0, 'g', 6);
    const QString name = profileName.isEmpty() ? tr("(unnamed)") : profileName;
    return tr("Profile %1 — %2").arg(name, parts.join(QStringLiteral(", ")));
}

PlotImageFormat plotImageFormat(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == u"svg")
        return PlotImageFormat::Svg;
    if (suffix == u"pdf")
        return PlotImageFormat::Pdf;
    return PlotImageFormat::Png;
}

bool writePlotImage(QCustomPlot *plot, const QString &path, const PlotImageOptions &options,
                    QString *error)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    const QSize size = options.size;
    if (size.width() < 100 || size.height() < kMinPlotHeight + 20 || size.width() > 16384 ||
        size.height() > 16384)
        return fail(tr("The image size %1×%2 is outside 100×100 … 16384×16384 pixels.")
                        .arg(size.width())
                        .arg(size.height()));
    bool ok = false;
    switch (plotImageFormat(path)) {
    case PlotImageFormat::Pdf:
        ok = plot->savePdf(path);
        break;
    case PlotImageFormat::Png: {
        const double scale = std::clamp(options.scale, 1.0, 4.0);
        const QSize layout(int(size.width() / scale), int(size.height() / scale));
        QImage image(size, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::white);
        {
            QCPPainter painter(&image);
            painter.scale(double(size.width()) / layout.width(),
                          double(size.height()) / layout.height());
            paint(plot, painter, layout, options.caption);
        }
        ok = image.save(path, "PNG");
        break;
    }
    case PlotImageFormat::Svg: {
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return fail(tr("Could not write %1: %2").arg(path, file.errorString()));
        QSvgGenerator svg;
        svg.setOutputDevice(&file);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(tr("HATPIC Tuner plot"));
        svg.setDescription(options.caption);
        {
            QCPPainter painter;
            if (painter.begin(&svg)) {
                painter.setMode(QCPPainter::pmVectorized); // pens as drawn, not cosmetic
                paint(plot, painter, size, options.caption);
                painter.end();
            }
        }
        file.close();
        ok = file.error() == QFileDevice::NoError && file.size() > 0;
        break;
    }
    }
    plot->replot(QCustomPlot::rpQueuedReplot); // back to the widget's own layout
    if (!ok)
        return fail(tr("Could not write %1.").arg(path));
    return true;
}

} // namespace hatpic
