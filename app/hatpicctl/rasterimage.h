// PNG for hatpicctl's charts: the SVG a chart is drawn as, rendered by Qt SVG on Qt's
// offscreen platform (no display needed). Only a run that asks for a PNG starts Qt's GUI
// layer; every other run of hatpicctl stays a QtCore program.
#pragma once

#include <QByteArray>
#include <QString>

#include <memory>

class QCoreApplication;

namespace hatpic::cli {

//! Empty when this hatpicctl draws PNG (built with Qt's GUI and SVG libraries,
//! HATPIC_BUILD_UI), else the sentence saying why not and what to do instead.
QString pngUnavailable();

//! The application object for these arguments: a QGuiApplication on the offscreen platform
//! when they ask for a PNG (`--png`) and pngUnavailable() is empty, else a QCoreApplication. Call
//! it before any other thread starts (it may set QT_QPA_PLATFORM).
std::unique_ptr<QCoreApplication> makeApplication(int &argc, char **argv);

//! `svg` as PNG, `scale` times its own size; empty, with `*error` saying why, when it cannot be
//! (an invalid SVG, no GUI application, pngUnavailable()).
QByteArray svgToPng(const QByteArray &svg, double scale, QString *error);

} // namespace hatpic::cli
