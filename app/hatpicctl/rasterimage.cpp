#include "rasterimage.h"

#include <QBuffer>
#include <QCoreApplication>

#include <cstring>

#ifdef HATPIC_HATPICCTL_PNG
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QSvgRenderer>
#endif

namespace hatpic::cli {

using namespace Qt::StringLiterals;

QString pngUnavailable()
{
#ifdef HATPIC_HATPICCTL_PNG
    return {};
#else
    return u"this hatpicctl was built without Qt's GUI and SVG libraries (HATPIC_BUILD_UI=OFF); "
           u"write --svg and convert it"_s;
#endif
}

std::unique_ptr<QCoreApplication> makeApplication(int &argc, char **argv)
{
#ifdef HATPIC_HATPICCTL_PNG
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--png") == 0 || std::strncmp(argv[i], "--png=", 6) == 0) {
            qputenv("QT_QPA_PLATFORM", "offscreen"); // a file is drawn, nothing is shown
            // The platform's start-up notes ("XDG_RUNTIME_DIR not set" on a server) are not
            // the user's business: hatpicctl reports its failures in its own sentences.
            const QtMessageHandler previous = qInstallMessageHandler(
                [](QtMsgType, const QMessageLogContext &, const QString &) {});
            auto app = std::make_unique<QGuiApplication>(argc, argv);
            qInstallMessageHandler(previous);
            return app;
        }
    }
#endif
    return std::make_unique<QCoreApplication>(argc, argv);
}

QByteArray svgToPng(const QByteArray &svg, double scale, QString *error)
{
#ifdef HATPIC_HATPICCTL_PNG
    if (!qobject_cast<QGuiApplication *>(QCoreApplication::instance())) {
        *error = u"drawing a PNG needs hatpicctl's GUI application (started by --png)"_s;
        return {};
    }
    QSvgRenderer renderer(svg);
    if (!renderer.isValid() || renderer.defaultSize().isEmpty()) {
        *error = u"the chart is not a valid SVG image"_s;
        return {};
    }
    QImage image(renderer.defaultSize() * scale, QImage::Format_RGB32);
    image.fill(Qt::white);
    {
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setRenderHint(QPainter::TextAntialiasing);
        renderer.render(&painter);
    }
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG")) {
        *error = u"Qt could not encode the PNG image"_s;
        return {};
    }
    return png;
#else
    Q_UNUSED(svg);
    Q_UNUSED(scale);
    *error = pngUnavailable();
    return {};
#endif
}

} // namespace hatpic::cli
